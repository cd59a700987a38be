#version 450 core
// Coherent silhouettes' fit on the GPU (Kalnins et al. 2003): steps 3. and 4. of
// common/strokes/coherent_silhouettes.hpp, in double as the reference makes them, one
// invocation per run: its votes sorted, split into groups, the groups' sections claimed and
// each section's t fitted on its knots by the normal equations, solved as a banded LDL^T
// (the reference: Eigen's dense LDLT). Scratch per run: its groups and claims from its first
// vote's slot (claims two a vote), its normal equations from its first knot's slot.
// One run a workgroup: llvmpipe runs at most 65535 loop iterations in a SIMD batch, all its
// loops and lanes together (LP_MAX_TGSI_LOOP_ITERATIONS), so that a run of many votes or
// sections would cut another's loops short in a shared batch (found by BrushFitParity's hard
// cases: tests/strokes/brush_fit_test.cpp).
layout(local_size_x = 1) in;

struct Vote {  // gpu/strokes/brush_fit.cpp VoteRecord
  double s, t;
  uint stroke, group, path, pad;  // group: what 3. makes of it
};
struct Run {  // gpu/strokes/brush_fit.hpp FitRunRecord
  double length;
  uint first_vote, vote_count, first_knot, knot_count, path, pad;  // knot_count, path: written
};
struct Group {  // the stroke it follows, its first and last vote, its size, and (by slot) the
  uint stroke, first, last, size, order, pad;  // groups in the order they claim
};
struct Claim {  // a section [from, to]; its votes are its group's in [piece_from, piece_to]
  double from, to, piece_from, piece_to;
  uint group, pad;
};
struct Row {  // row k of the normal equations: M(k, k), M(k, k + 1), M(k, k + 2), b(k)
  double m0, m1, m2, b;
};
struct Params {  // common/strokes/coherent_silhouettes.hpp CoherenceParams
  double sample_px, jump_px, knot_px, scale_weight, distort_weight;
  uint claim_votes, run_count;
};

layout(std430, binding = 0) buffer Votes { Vote votes[]; };
layout(std430, binding = 1) buffer Runs { Run runs[]; };
layout(std430, binding = 2) buffer Groups { Group groups[]; };
layout(std430, binding = 3) buffer Claims { Claim claims[]; };
layout(std430, binding = 4) buffer Rows { Row rows[]; };
layout(std430, binding = 5) writeonly buffer Knots { dvec2 knots[]; };
layout(std430, binding = 6) readonly buffer FitParams { Params p; };

const uint kNewBrushPath = 0xffffffffu;  // common/strokes/coherent_silhouettes.hpp

// The reference's total order of votes: s, then stroke, then t.
bool before(Vote a, Vote b) {
  if (a.s != b.s) return a.s < b.s;
  if (a.stroke != b.stroke) return a.stroke < b.stroke;
  return a.t < b.t;
}

// Shell sort (Ciura's gaps, then x 2.25): the votes come in any order (the bucketing's
// atomics), and an insertion sort of a long run's would loop ~n^2 / 4 times, past the 65535
// loop iterations llvmpipe allows a shader batch before it cuts every loop short
// (LP_MAX_TGSI_LOOP_ITERATIONS). The total order makes any sort's result the same.
void sort_votes(uint first, uint count) {
  const uint gaps[11] = uint[](8858u, 3937u, 1750u, 701u, 301u, 132u, 57u, 23u, 10u, 4u, 1u);
  for (uint g = 0u; g < 11u; ++g) {
    uint gap = gaps[g];
    for (uint i = first + gap; i < first + count; ++i) {
      Vote v = votes[i];
      uint j = i;
      for (; j >= first + gap && before(v, votes[j - gap]); j -= gap) votes[j] = votes[j - gap];
      votes[j] = v;
    }
  }
}

// 3. Each vote joins the group still growing of its stroke (the last one made for it) while
// it follows that group's last vote within 3 sample_px of s and its t changes by |Δs| within
// jump_px; else it starts a group. The groups' count.
uint make_groups(uint first, uint count) {
  uint n = 0u;
  for (uint i = first; i < first + count; ++i) {
    Vote v = votes[i];
    uint open = n;
    for (uint g = n; g > 0u && open == n; --g)
      if (groups[first + g - 1u].stroke == v.stroke) open = g - 1u;
    if (open < n) {
      Vote last = votes[groups[first + open].last];
      double ds = v.s - last.s;
      if (ds <= 3.0lf * p.sample_px && abs(abs(v.t - last.t) - ds) <= p.jump_px) {
        groups[first + open].last = i, ++groups[first + open].size;
        votes[i].group = open;
        continue;
      }
    }
    groups[first + n] = Group(v.stroke, i, i, 1u, n, 0u);
    votes[i].group = n++;
  }
  return n;
}

// The groups in order of size, largest first, equal sizes in the order they were made.
void order_groups(uint first, uint n) {
  for (uint k = 1u; k < n; ++k) {
    uint g = groups[first + k].order, j = k;
    for (; j > 0u && groups[first + g].size > groups[first + groups[first + j - 1u].order].size; --j)
      groups[first + j].order = groups[first + j - 1u].order;
    groups[first + j].order = g;
  }
}

// The votes of group g within [a, b].
uint votes_within(uint first, uint g, double a, double b) {
  uint own = 0u;
  for (uint i = groups[first + g].first; i <= groups[first + g].last; ++i)
    if (votes[i].group == g && votes[i].s >= a && votes[i].s <= b) ++own;
  return own;
}

// A piece [x, y] of group g's span that no claim took: a claim where claim_votes of its votes lie,
// added after the nc claims sorted so far.
uint add_piece(uint c0, uint nc, uint first, uint g, double x, double y) {
  if (votes_within(first, g, x, y) < p.claim_votes) return nc;
  claims[c0 + nc] = Claim(x, y, x, y, g, 0u);
  return nc + 1u;
}

// The first of the claims [c0, c0 + nc) that reaches x (to >= x): they are disjoint and
// sorted by from, so by to too; the claims before it end before x (claim_span skips them).
uint first_reaching(uint c0, uint nc, double x) {
  uint lo = 0u, hi = nc;
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (claims[c0 + mid].to < x) lo = mid + 1u; else hi = mid;
  }
  return lo;
}

// 3. Group g's span less the claims [c0, c0 + nc) (sorted by from, then to), split at their
// ends: the pieces the reference's interval subtraction leaves, each claimed where its
// votes are enough, appended. The claims' count after.
uint claim_span(uint c0, uint nc, uint first, uint g) {
  double a = votes[groups[first + g].first].s, b = votes[groups[first + g].last].s, x = a;
  uint made = nc;
  bool open = true;  // [x, b] is still free
  for (uint k = first_reaching(c0, nc, a); k < nc && open; ++k) {
    Claim c = claims[c0 + k];
    if (c.to < x) continue;    // before the piece
    if (c.from > b) break;     // past the span, as every claim after it
    if (c.from > x) made = add_piece(c0, made, first, g, x, min(b, c.from));
    if (c.to < b)
      x = max(x, c.to);
    else
      open = false;
  }
  if (open) made = add_piece(c0, made, first, g, x, b);
  return made;
}

bool claim_before(Claim a, Claim b) { return a.from < b.from || (a.from == b.from && a.to < b.to); }

// The claims [c0 + sorted, c0 + n) into the sorted ones.
void insert_claims(uint c0, uint sorted, uint n) {
  for (uint i = sorted; i < n; ++i) {
    Claim c = claims[c0 + i];
    uint j = i;
    for (; j > 0u && claim_before(c, claims[c0 + j - 1u]); --j) claims[c0 + j] = claims[c0 + j - 1u];
    claims[c0 + j] = c;
  }
}

// 3. The sections: largest group first, each claims what of its span no larger group
// claimed; gaps between claims go half to either side, the run's ends to the nearest claim.
uint make_sections(uint first, uint n_groups, double length) {
  uint c0 = 2u * first, nc = 0u;
  for (uint k = 0u; k < n_groups; ++k) {
    uint made = claim_span(c0, nc, first, groups[first + k].order);
    insert_claims(c0, nc, made);
    nc = made;
  }
  for (uint i = 0u; i + 1u < nc; ++i) {
    double mid = 0.5lf * (claims[c0 + i].to + claims[c0 + i + 1u].from);
    claims[c0 + i].to = mid, claims[c0 + i + 1u].from = mid;
  }
  if (nc > 0u) claims[c0].from = 0.0lf, claims[c0 + nc - 1u].to = length;
  return nc;
}

// σ of 4.: the sign of the least-squares slope of t over the section's votes (+1 for one).
double direction(uint first, Claim c) {
  precise double ms = 0.0lf, mt = 0.0lf, n = 0.0lf;
  for (uint i = groups[first + c.group].first; i <= groups[first + c.group].last; ++i)
    if (votes[i].group == c.group && votes[i].s >= c.piece_from && votes[i].s <= c.piece_to)
      ms += votes[i].s, mt += votes[i].t, n += 1.0lf;
  ms /= n, mt /= n;
  precise double covariance = 0.0lf;
  for (uint i = groups[first + c.group].first; i <= groups[first + c.group].last; ++i)
    if (votes[i].group == c.group && votes[i].s >= c.piece_from && votes[i].s <= c.piece_to)
      covariance += (votes[i].s - ms) * (votes[i].t - mt);
  return covariance < 0.0lf ? -1.0lf : 1.0lf;
}

// M(i, j) += w ci cj for j >= i (M is symmetric: its upper band), as the reference adds them.
void add_m(uint r0, uint i, uint j, double w, double ci, double cj) {
  precise double add = w * ci * cj;
  uint d = j - i;
  precise double sum = (d == 0u ? rows[r0 + i].m0 : d == 1u ? rows[r0 + i].m1 : rows[r0 + i].m2) + add;
  if (d == 0u) rows[r0 + i].m0 = sum;
  else if (d == 1u) rows[r0 + i].m1 = sum;
  else rows[r0 + i].m2 = sum;
}

void add_b(uint r0, uint i, double w, double ci, double target) {
  precise double add = w * ci * target;
  precise double sum = rows[r0 + i].b + add;
  rows[r0 + i].b = sum;
}

// Adds w (sum_k c_k x_{i_k} - target)^2 for a row of 2 or 3 consecutive unknowns from i.
void add_term(uint r0, uint i, uint count, dvec3 c, double target, double w) {
  for (uint a = 0u; a < count; ++a) {
    add_b(r0, i + a, w, c[a], target);
    for (uint e = a; e < count; ++e) add_m(r0, i + a, i + e, w, c[a], c[e]);
  }
}

// rounds half away from zero, as std::lround does, for x >= 0
double round_half_up(double x) {
  double r = floor(x);
  return x - r >= 0.5lf ? r + 1.0lf : r;
}

// 4. One section's knots at `at`; false where the solve is not finite.
bool fit_section(uint first, uint r0, Claim c, uint at, out uint written) {
  double length = c.to - c.from;
  uint n = uint(max(1.0lf, round_half_up(length / p.knot_px)));
  double h = length / double(n), sigma = direction(first, c);
  for (uint k = 0u; k <= n; ++k) rows[r0 + k] = Row(0.0lf, 0.0lf, 0.0lf, 0.0lf);
  for (uint i = groups[first + c.group].first; i <= groups[first + c.group].last; ++i) {  // coherence
    Vote v = votes[i];
    if (v.group != c.group || v.s < c.piece_from || v.s > c.piece_to) continue;
    double x = h > 0.0lf ? clamp((v.s - c.from) / h, 0.0lf, double(n)) : 0.0lf;
    uint k = min(uint(x), n - 1u);
    add_term(r0, k, 2u, dvec3(double(k + 1u) - x, x - double(k), 0.0lf), v.t, 1.0lf);
  }
  for (uint k = 0u; k < n; ++k) add_term(r0, k, 2u, dvec3(-1.0lf, 1.0lf, 0.0lf), sigma * h, p.scale_weight);
  for (uint k = 1u; k < n; ++k) add_term(r0, k - 1u, 3u, dvec3(1.0lf, -2.0lf, 1.0lf), 0.0lf, p.distort_weight);
  // LDL^T of the band: row k keeps d_k and L(k+1, k), L(k+2, k); then b is solved in place.
  for (uint k = 0u; k <= n; ++k) {
    precise double d = rows[r0 + k].m0;
    if (k >= 1u) d -= rows[r0 + k - 1u].m1 * rows[r0 + k - 1u].m1 * rows[r0 + k - 1u].m0;
    if (k >= 2u) d -= rows[r0 + k - 2u].m2 * rows[r0 + k - 2u].m2 * rows[r0 + k - 2u].m0;
    rows[r0 + k].m0 = d;  // d_k; M(k, k+1) and M(k, k+2) still above it
    precise double l1 = rows[r0 + k].m1;
    if (k >= 1u) l1 -= rows[r0 + k - 1u].m2 * rows[r0 + k - 1u].m1 * rows[r0 + k - 1u].m0;
    rows[r0 + k].m1 = l1 / d;
    rows[r0 + k].m2 = rows[r0 + k].m2 / d;
  }
  for (uint k = 1u; k <= n; ++k) {  // L y = b
    precise double y = rows[r0 + k].b - rows[r0 + k - 1u].m1 * rows[r0 + k - 1u].b;
    if (k >= 2u) y -= rows[r0 + k - 2u].m2 * rows[r0 + k - 2u].b;
    rows[r0 + k].b = y;
  }
  for (uint k = 0u; k <= n; ++k) rows[r0 + k].b /= rows[r0 + k].m0;  // D z = y
  for (uint k = n; k-- > 0u;) {                                       // L^T x = z
    precise double x = rows[r0 + k].b - rows[r0 + k].m1 * rows[r0 + k + 1u].b;
    if (k + 2u <= n) x -= rows[r0 + k].m2 * rows[r0 + k + 2u].b;
    rows[r0 + k].b = x;
  }
  for (uint k = 0u; k <= n; ++k) {
    double t = rows[r0 + k].b;
    if (isnan(t) || isinf(t)) return false;
    knots[at + k] = dvec2(c.from + double(k) * h, t);
  }
  written = n + 1u;
  return true;
}

// 5. The brush path of the largest section: the most votes, the first in s among equals.
uint largest_path(uint first, uint sections) {
  uint most = 0u, path = kNewBrushPath;
  for (uint i = 0u; i < sections; ++i) {
    Claim c = claims[2u * first + i];
    uint own = votes_within(first, c.group, c.piece_from, c.piece_to);
    if (own > most) most = own, path = votes[groups[first + c.group].first].path;
  }
  return path;
}

void at_run(uint r) {
  Run run = runs[r];
  runs[r].knot_count = 0u, runs[r].path = kNewBrushPath;
  if (!(run.length > 0.0lf) || run.vote_count == 0u) return;
  uint first = run.first_vote;
  sort_votes(first, run.vote_count);
  uint n_groups = make_groups(first, run.vote_count);
  order_groups(first, n_groups);
  uint sections = make_sections(first, n_groups, run.length), at = run.first_knot;
  for (uint i = 0u; i < sections; ++i) {
    uint written;
    if (!fit_section(first, run.first_knot, claims[2u * first + i], at, written)) return;
    at += written;
  }
  runs[r].knot_count = at - run.first_knot, runs[r].path = largest_path(first, sections);
}

void main() {
  for (uint r = gl_GlobalInvocationID.x; r < p.run_count; r += gl_NumWorkGroups.x) at_run(r);
}
