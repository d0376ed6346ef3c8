#pragma once
// Seam pairing: every seam edge matched to its partner, runs of seam edges gathered into
// chains, and the chains paired into the seams that are printed with one label.

#include <array>
#include <string>
#include <vector>

#include "nodes/layout/pieces.h"

namespace papercraft::layout_internal {

/// Seam edges of all pieces, each matched to the edge with the same label running the other
/// way between the same 3D points (label_seams makes glued points bit-identical).
struct SeamEdges {
  std::vector<std::array<int, 3>> refs;           // piece, loop, index in loop
  std::vector<std::vector<std::vector<int>>> id;  // [piece][loop][index] -> edge id or -1
  std::vector<int> partner;                       // edge id or -1
};

/// Numbers the seam edges of `pieces` and matches each to its partner.
SeamEdges match_seam_edges(const std::vector<Piece>& pieces, const std::vector<StripData>& strips);

/// A run of consecutive seam edges with one label on one boundary loop whose partners run
/// consecutively the other way on one loop (so a cap glued to a band split in two gets two
/// chains), or of unmatched edges with one label.
struct Chain {
  int piece = -1;
  int loop = -1;
  int start = 0;
  int count = 0;
  bool closed = false;
  std::string label;
  Vec3 first = Vec3::Zero();  // 3D start and end points
  Vec3 last = Vec3::Zero();
  int partner_edge = -1;  // partner of the first edge, when matched
};

/// The chains of every boundary loop of every piece (a loop that is one chain all round is
/// `closed`); a run of unmatched edges breaks where an edge comes straight back in 3D (ends
/// within tolerance3d of where the previous edge began).
std::vector<Chain> seam_chains(const std::vector<Piece>& pieces,
                               const std::vector<StripData>& strips, const SeamEdges& seams,
                               double tolerance3d);

/// Two chains glued to each other and the label printed on both.
struct SeamPair {
  int first = -1;  // chain indices; second = -1 when the seam has no partner
  int second = -1;
  std::string printed;
};

/// Pairs chains by their matched edges, else chains of one label by their nearest ends;
/// a label with more than one pair is printed with a suffix per pair (A1.1, A1.2).
std::vector<SeamPair> pair_chains(const std::vector<Chain>& chains, const SeamEdges& seams,
                                  const std::vector<Piece>& pieces, double tolerance3d,
                                  std::vector<std::string>& warnings);

/// Length of `chain` on its piece in millimetres.
double chain_length(const StripData& data, const Piece& piece, const Chain& chain);

}  // namespace papercraft::layout_internal
