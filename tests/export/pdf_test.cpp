#include "nodes/export/pdf.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "core/errors.h"
#include "nodes/layout/pages.h"
#include "support/layout_strips.h"

namespace papercraft {
namespace {

using testing::cell_strip;
using testing::prism_strips;
using testing::square_footprint;

std::filesystem::path temporary(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("papercraft_pdf_test_" + std::to_string(::getpid()) + "_" + name);
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Page objects in the file ("/Type /Page", not "/Pages").
int page_objects(const std::string& pdf) {
  const std::regex page("/Type\\s*/Page(?![a-zA-Z])");
  return static_cast<int>(
      std::distance(std::sregex_iterator(pdf.begin(), pdf.end(), page), std::sregex_iterator()));
}

// Pages as poppler's pdfinfo reads them, or -1 without pdfinfo.
int pdfinfo_pages(const std::filesystem::path& path) {
  FILE* pipe = ::popen(("pdfinfo '" + path.string() + "' 2>/dev/null").c_str(), "r");
  if (!pipe) return -1;
  std::string output;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  if (::pclose(pipe) != 0) return -1;
  std::smatch match;
  if (!std::regex_search(output, match, std::regex("Pages:\\s+(\\d+)"))) return -1;
  return std::stoi(match[1]);
}

TEST(ExportPdf, OnePdfPagePerLayoutPage) {
  std::vector<FlatStrip> strips = prism_strips(square_footprint(40), 60, 0);
  strips.push_back(cell_strip(3, 60, 1, 10, 20));
  strips.push_back(cell_strip(4, 9, 10, 20, 20));
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  ASSERT_GE(layout.pages.size(), 2u);
  for (StylePreset preset : {StylePreset::Print, StylePreset::Laser, StylePreset::Cutter}) {
    const auto path = temporary("pattern.pdf");
    StyleOptions style;
    style.preset = preset;
    write_pattern_pdf(layout, path, style);
    const std::string pdf = read(path);
    EXPECT_EQ(pdf.rfind("%PDF", 0), 0u);
    EXPECT_EQ(page_objects(pdf), static_cast<int>(layout.pages.size()));
    const int info = pdfinfo_pages(path);
    if (info >= 0) {
      EXPECT_EQ(info, static_cast<int>(layout.pages.size()));
    }
    // A4 in points.
    EXPECT_NE(pdf.find("/MediaBox [ 0 0 595.27"), std::string::npos);
    std::filesystem::remove(path);
  }
}

TEST(ExportPdf, EmptyLayoutGivesOneBlankPage) {
  PatternLayout layout;
  const auto path = temporary("empty.pdf");
  write_pattern_pdf(layout, path);
  EXPECT_EQ(page_objects(read(path)), 1);
  std::filesystem::remove(path);
}

TEST(ExportPdf, UnwritablePathThrows) {
  PatternLayout layout;
  EXPECT_THROW(write_pattern_pdf(layout, "/nonexistent-directory/papercraft/pattern.pdf"),
               IOException);
}

}  // namespace
}  // namespace papercraft
