#pragma once
// gzip (RFC 1952) through zlib, for text embedded in a page: assembly.html carries its model's
// data gzip-compressed, and the browser's DecompressionStream opens it.

#include <string>
#include <string_view>

namespace papercraft {

/// `bytes` compressed as one gzip member (deflate at level 9, no file name, time 0), so the
/// same bytes always give the same result.
/// \throws InternalError if zlib fails (it runs out of memory).
std::string gzip(std::string_view bytes);

}  // namespace papercraft
