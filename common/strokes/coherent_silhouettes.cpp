// Coherent stylized silhouettes (Kalnins et al. 2003): see common/strokes/coherent_silhouettes.hpp.
#include "common/strokes/coherent_silhouettes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include <Eigen/Dense>

#include "common/strokes/stroke.hpp"
#include "common/strokes/strokes.hpp"
#include "common/util/segment_grid.hpp"

namespace plumbago {

namespace {

// A piece of a visible silhouette run of the new frame: window ends, s at them (from the
// run's start) and their linear view depths.
struct RunPiece {
  uint32_t run;
  glm::dvec2 a, b;
  double sa, sb, da, db;
};

// The pieces of the new frame's visible silhouette runs on a grid of `cell` px.
class PieceGrid {
 public:
  PieceGrid(const WindowLines& lines, const Visibility& visibility, const WindowProjection& project, double cell)
      : grid_(lines.width, lines.height, cell) {
    for (uint32_t r = 0; r < visibility.runs.size(); ++r) {
      const VisibleRun& run = visibility.runs[r];
      const WindowPath& path = lines.paths[run.path];
      if (path.kind != LineKind::Silhouette || run.window.size() < 2) continue;
      double s = 0, d = project(world_at(path, run.s0)).z;
      for (size_t j = 0; j + 1 < run.window.size(); ++j) {
        double next_s = s + glm::distance(run.window[j], run.window[j + 1]);
        double next_d = project(world_at(path, run.s0 + next_s)).z;
        grid_.add(run.window[j], run.window[j + 1], uint32_t(pieces_.size()));
        pieces_.push_back({r, run.window[j], run.window[j + 1], s, next_s, d, next_d});
        s = next_s, d = next_d;
      }
    }
  }

  // The nearest point within `radius` of q on a piece whose depth there agrees with q.z;
  // among equals, the first piece's (in run order, then along the run).
  std::optional<BrushVote> nearest(glm::dvec3 q, double radius, double depth_tolerance) const {
    std::optional<BrushVote> best;
    double best_distance = radius;
    uint32_t best_piece = std::numeric_limits<uint32_t>::max();
    grid_.near(glm::dvec2(q) - radius, glm::dvec2(q) + radius, [&](uint32_t i) {
      const RunPiece& piece = pieces_[i];
      auto [f, distance] = nearest_on(piece.a, piece.b, glm::dvec2(q));
      double depth = std::lerp(piece.da, piece.db, f);
      bool nearer = distance < best_distance || (distance == best_distance && i < best_piece);
      if (!nearer || std::abs(depth - q.z) > depth_tolerance * q.z) return;
      best_distance = distance, best_piece = i;
      best = BrushVote{piece.run, std::lerp(piece.sa, piece.sb, f), 0.0, 0, 0};
    });
    return best;
  }

 private:
  SegmentGrid grid_;
  std::vector<RunPiece> pieces_;
};

// 3. The votes of one run, in order of s (then of stroke and t), split into groups.
std::vector<std::vector<BrushVote>> vote_groups(std::vector<BrushVote> votes, const CoherenceParams& p) {
  // A total order: votes tie in s where they clamp to an end of the run.
  std::sort(votes.begin(), votes.end(), [](const BrushVote& a, const BrushVote& b) {
    return std::tie(a.s, a.stroke, a.t) < std::tie(b.s, b.stroke, b.t);
  });
  std::vector<std::vector<BrushVote>> groups;
  std::map<uint32_t, size_t> open;  // per stroke voting, its group still growing
  for (const BrushVote& v : votes) {
    auto it = open.find(v.stroke);
    if (it != open.end()) {
      const BrushVote& last = groups[it->second].back();
      double ds = v.s - last.s;
      if (ds <= 3 * p.sample_px && std::abs(std::abs(v.t - last.t) - ds) <= p.jump_px) {
        groups[it->second].push_back(v);
        continue;
      }
    }
    open[v.stroke] = groups.size();
    groups.push_back({v});
  }
  return groups;
}

// A stretch [from, to] of the run and the votes of the group that parameterizes it.
struct Section {
  double from, to;
  std::vector<BrushVote> votes;
};

// The votes of `group` from a to b.
std::vector<BrushVote> votes_within(const std::vector<BrushVote>& group, double a, double b) {
  std::vector<BrushVote> out;
  for (const BrushVote& v : group)
    if (v.s >= a && v.s <= b) out.push_back(v);
  return out;
}

// 3. The groups, largest first, each claim what of their span (first to last vote) no
// larger group claimed, where claim_votes of their votes lie; gaps between claims go half to
// either side, the run's ends to the nearest claim. In order of s.
std::vector<Section> sections(std::vector<std::vector<BrushVote>> groups, double length_px, size_t claim_votes) {
  std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  std::vector<Section> claims;
  for (const std::vector<BrushVote>& g : groups) {
    std::vector<std::pair<double, double>> free{{g.front().s, g.back().s}};
    for (const Section& c : claims) {
      std::vector<std::pair<double, double>> left;
      for (auto [a, b] : free) {
        if (c.from > a) left.push_back({a, std::min(b, c.from)});
        if (c.to < b) left.push_back({std::max(a, c.to), b});
      }
      free = left;
    }
    for (auto [a, b] : free)
      if (std::vector<BrushVote> own = votes_within(g, a, b); own.size() >= claim_votes) claims.push_back({a, b, own});
  }
  std::sort(claims.begin(), claims.end(),
            [](const Section& a, const Section& b) { return std::tie(a.from, a.to) < std::tie(b.from, b.to); });
  for (size_t i = 0; i + 1 < claims.size(); ++i)
    claims[i].to = claims[i + 1].from = 0.5 * (claims[i].to + claims[i + 1].from);
  if (!claims.empty()) claims.front().from = 0, claims.back().to = length_px;
  return claims;
}

// σ of 4.: the sign of the least-squares slope of t over s (+1 for a single vote).
double direction(const std::vector<BrushVote>& votes) {
  double ms = 0, mt = 0;
  for (const BrushVote& v : votes) ms += v.s, mt += v.t;
  ms /= double(votes.size()), mt /= double(votes.size());
  double covariance = 0;
  for (const BrushVote& v : votes) covariance += (v.s - ms) * (v.t - mt);
  return covariance < 0 ? -1.0 : 1.0;
}

// Adds weight (row . x - target)^2 to the normal equations (M, b).
void add_term(Eigen::MatrixXd& m, Eigen::VectorXd& b, const std::vector<std::pair<int, double>>& row, double target,
              double weight) {
  for (auto [i, ci] : row) {
    b[i] += weight * ci * target;
    for (auto [j, cj] : row) m(i, j) += weight * ci * cj;
  }
}

// 4. One section's fit.
BrushParameter fit_section(const Section& section, const CoherenceParams& p) {
  const double length = section.to - section.from;
  const int n = std::max(1, int(std::lround(length / p.knot_px)));
  const double h = length / n, sigma = direction(section.votes);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n + 1, n + 1);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n + 1);
  for (const BrushVote& v : section.votes) {  // coherence
    double at = h > 0 ? std::clamp((v.s - section.from) / h, 0.0, double(n)) : 0.0;
    int k = std::min(int(at), n - 1);
    add_term(m, b, {{k, k + 1 - at}, {k + 1, at - k}}, v.t, 1.0);
  }
  for (int k = 0; k < n; ++k) add_term(m, b, {{k, -1.0}, {k + 1, 1.0}}, sigma * h, p.scale_weight);  // uniformity
  for (int k = 1; k < n; ++k) add_term(m, b, {{k - 1, 1.0}, {k, -2.0}, {k + 1, 1.0}}, 0.0, p.distort_weight);
  Eigen::VectorXd t = m.ldlt().solve(b);
  if (!t.allFinite()) return {};
  BrushParameter out;
  for (int k = 0; k <= n; ++k) out.push_back({section.from + k * h, t[k]});
  return out;
}

}  // namespace

std::vector<BrushSample> brush_samples(const WindowLines& lines, const Visibility& visibility,
                                       const std::vector<RunBrush>& brushes, const CoherenceParams& p, uint32_t seed) {
  std::vector<BrushSample> out;
  std::vector<uint32_t> ordinals = run_ordinals(visibility.runs);
  for (uint32_t i = 0; i < visibility.runs.size(); ++i) {
    const VisibleRun& run = visibility.runs[i];
    const WindowPath& path = lines.paths[run.path];
    if (path.kind != LineKind::Silhouette) continue;
    double length = run.s1 - run.s0;
    int n = std::max(1, int(std::ceil(length / p.sample_px)));
    const RunBrush brush = i < brushes.size() ? brushes[i] : RunBrush{};
    const uint32_t key = brush_path_key(brush, seed, path, ordinals[i]);
    for (int j = 0; j <= n - (run.closed ? 1 : 0); ++j) {
      double s = length * j / n;
      out.push_back({world_at(path, run.s0 + s), brush_t(brush.knots, s), i, key});
    }
  }
  return out;
}

std::vector<BrushVote> brush_votes(const std::vector<BrushSample>& previous, const Camera& camera,
                                   const WindowLines& lines, const Visibility& visibility, const CoherenceParams& p) {
  WindowProjection project(camera, lines.width, lines.height);
  PieceGrid grid(lines, visibility, project, std::max(4.0, 2 * p.search_px));
  std::vector<BrushVote> out;
  for (const BrushSample& b : previous) {
    glm::dvec3 seen = project(b.world);
    if (!(seen.z > 0)) continue;
    if (std::optional<BrushVote> v = grid.nearest(seen, p.search_px, p.depth_tolerance))
      out.push_back({v->run, v->s, b.t, b.stroke, b.path});
  }
  return out;
}

RunBrush fit_brush_parameter(std::vector<BrushVote> votes, double length_px, const CoherenceParams& p) {
  if (!(length_px > 0) || votes.empty()) return {};
  RunBrush out;
  size_t most = 0;
  for (const Section& section :
       sections(vote_groups(std::move(votes), p), length_px, size_t(std::max(1, p.claim_votes)))) {
    BrushParameter knots = fit_section(section, p);
    if (knots.empty()) return {};
    out.knots.insert(out.knots.end(), knots.begin(), knots.end());
    if (section.votes.size() > most) most = section.votes.size(), out.path = section.votes.front().path;  // 5.
  }
  return out;
}

std::vector<RunBrush> coherent_parameters(const std::vector<BrushSample>& previous, const Camera& camera,
                                          const WindowLines& lines, const Visibility& visibility,
                                          const CoherenceParams& p) {
  std::vector<std::vector<BrushVote>> per_run(visibility.runs.size());
  for (const BrushVote& v : brush_votes(previous, camera, lines, visibility, p)) per_run[v.run].push_back(v);
  std::vector<RunBrush> out;
  for (size_t r = 0; r < per_run.size(); ++r)
    out.push_back(fit_brush_parameter(std::move(per_run[r]), visibility.runs[r].s1 - visibility.runs[r].s0, p));
  return out;
}

}  // namespace plumbago
