// Princeton Segmentation Benchmark metrics: hand-worked cases on a small strip, then the
// fixture table of /work/shared/notes/psb-metrics.md on the psb-dev models.
#include <segmat/evaluation/psb_metrics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

using namespace segmat;

namespace {

// A flat strip of four unit squares, each cut into two triangles of area 1/2 (A = 4, n = 8):
//
//   t0=5 ─ t1=6 ─ t2=7 ─ t3=8 ─ t4=9        y = 1
//    │  ╱  │  ╱  │  ╱  │  ╱  │
//   b0=0 ─ b1=1 ─ b2=2 ─ b3=3 ─ b4=4        y = 0
//
// Square x holds faces 2x = (b_x, b_x+1, t_x+1) and 2x+1 = (b_x, t_x+1, t_x), both counter-
// clockwise. Interior edges (a face on each side): the verticals at x = 1, 2, 3 and the four
// diagonals b_x–t_x+1. Edge lengths: 1 along the sides, √2 along the diagonals.
TriangleMesh
strip()
{
  std::vector<Eigen::Vector3d> v;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x <= 4; ++x)
      v.emplace_back(x, y, 0);
  std::vector<Eigen::Vector3i> f;
  for (int x = 0; x < 4; ++x) {
    f.emplace_back(x, x + 1, 5 + x + 1);
    f.emplace_back(x, 5 + x + 1, 5 + x);
  }
  return TriangleMesh(v, f);
}

// Average radius of the strip. Centroid (2, 1/2, 0); face centroids ((3x+2)/3, 1/3) and
// ((3x+1)/3, 2/3), so |dx| ∈ {4/3, 1/3, 2/3, 5/3} (each twice) and |dy| = 1/6:
// R = (1/4)·Σ sqrt(dx² + 1/36) = (√65 + √5 + √17 + √101) / 24 ≈ 1.019638.
const double kStripRadius =
    (std::sqrt(65.0) + std::sqrt(5.0) + std::sqrt(17.0) + std::sqrt(101.0)) / 24.0;

// P: squares 0–1 | 2–3 (cut: the vertical b2–t2). Q: square 0 | 1–3 (cut: b1–t1), odd ids.
const std::vector<int> kP{0, 0, 0, 0, 1, 1, 1, 1};
const std::vector<int> kQ{5, 5, 9, 9, 9, 9, 9, 9};
const std::vector<int> kOne(8, 3);

std::vector<int>
onePerFace(int n)
{
  std::vector<int> l(n);
  std::iota(l.begin(), l.end(), 0);
  return l;
}

PsbScores
scored(const PsbEvaluator& e, const std::vector<int>& s1, const std::vector<int>& s2)
{
  PsbScores s;
  EXPECT_TRUE(e.score(s1, s2, s));
  return s;
}

} // namespace

TEST(PsbMetrics, StripGeometry)
{
  const PsbEvaluator e(strip());
  ASSERT_TRUE(e.ready());
  EXPECT_EQ(e.numEvaluatedFaces(), 8u);
  EXPECT_DOUBLE_EQ(e.totalArea(), 4.0);
  EXPECT_NEAR(e.averageRadius(), kStripRadius, 1e-12);
  EXPECT_NEAR(kStripRadius, 1.019638, 1e-6);
}

TEST(PsbMetrics, IdenticalSegmentationsScoreZero)
{
  const PsbEvaluator e(strip());
  const PsbScores s = scored(e, kP, kP);
  EXPECT_DOUBLE_EQ(s.GCE, 0.0);
  EXPECT_DOUBLE_EQ(s.LCE, 0.0);
  EXPECT_DOUBLE_EQ(s.GCEf, 0.0);
  EXPECT_DOUBLE_EQ(s.LCEf, 0.0);
  EXPECT_DOUBLE_EQ(s.HD, 0.0);
  EXPECT_DOUBLE_EQ(s.Rm, 0.0);
  EXPECT_DOUBLE_EQ(s.Rf, 0.0);
  EXPECT_DOUBLE_EQ(s.RI, 0.0);
  ASSERT_TRUE(s.hasCD()); // both have a cut: CD is defined, and 0
  EXPECT_DOUBLE_EQ(s.CD, 0.0);
  EXPECT_EQ(s.count, 1);
  EXPECT_EQ(s.cd_count, 1);
}

TEST(PsbMetrics, TwoDifferentCutsByHand)
{
  // Cells (P segment, Q segment): (0,5) faces 0–1, (0,9) faces 2–3, (1,9) faces 4–7.
  // |P0| = |P1| = 4, |Q5| = 2, |Q9| = 6; every face has area 1/2, so area ratios = count ratios.
  // E12 = 1 − n_ij/|P_i|: 1/2 (2 faces), 1/2 (2 faces), 0 (4 faces) → ΣE12 = 2.
  // E21 = 1 − n_ij/|Q_j|: 0 (2 faces), 2/3 (2 faces), 1/3 (4 faces) → ΣE21 = 8/3.
  // GCE = min(2, 8/3)/8 = 1/4. LCE = (2·min(½,0) + 2·min(½,⅔) + 4·min(0,⅓))/8 = 1/8.
  // Hamming: best overlap per Q segment 1 + 2 = 3 → Rm = (4−3)/4 = 1/4; per P segment 1 + 2 = 3
  //          → Rf = 1/4; HD = 1/4.
  // Rand: ΣC(|P_i|,2) = 6+6 = 12, ΣC(|Q_j|,2) = 1+15 = 16, ΣC(n_ij,2) = 1+1+6 = 8;
  //       (12 + 16 − 2·8) / (8·⌊7/2⌋) = 12/24 = 1/2 (the textbook divisor 28 would give 3/7).
  // CD: Z_P = {b2, t2}, Z_Q = {b1, t1}; each is one unit edge from the other cut:
  //     (1 + 1 + 1 + 1) / 4 / R = 1/R.
  const PsbEvaluator e(strip());
  const PsbScores s = scored(e, kP, kQ);
  EXPECT_NEAR(s.GCE, 0.25, 1e-12);
  EXPECT_NEAR(s.LCE, 0.125, 1e-12);
  EXPECT_NEAR(s.GCEf, 0.25, 1e-12);
  EXPECT_NEAR(s.LCEf, 0.125, 1e-12);
  EXPECT_NEAR(s.Rm, 0.25, 1e-12);
  EXPECT_NEAR(s.Rf, 0.25, 1e-12);
  EXPECT_NEAR(s.HD, 0.25, 1e-12);
  EXPECT_NEAR(s.RI, 0.5, 1e-12);
  ASSERT_TRUE(s.hasCD());
  EXPECT_NEAR(s.CD, 1.0 / kStripRadius, 1e-12);

  // Swapping the two swaps Rm and Rf and changes nothing else.
  const PsbScores t = scored(e, kQ, kP);
  EXPECT_NEAR(t.Rm, s.Rf, 1e-12);
  EXPECT_NEAR(t.Rf, s.Rm, 1e-12);
  EXPECT_NEAR(t.GCE, s.GCE, 1e-12);
  EXPECT_NEAR(t.LCE, s.LCE, 1e-12);
  EXPECT_NEAR(t.RI, s.RI, 1e-12);
  EXPECT_NEAR(t.CD, s.CD, 1e-12);
}

TEST(PsbMetrics, AreaVersusFaceCount)
{
  // Stretch square 1 to width 3 (every vertex with x >= 2 moves by +2): faces 2, 3 get area 3/2,
  // the others keep 1/2; A = 6. Compare Q (square 0 | 1–3) with R3 (squares 0–2 | 3).
  // Cells (Q, R3): (5,A) faces 0–1 area 1; (9,A) faces 2–5 area 3 + 1 = 4; (9,B) faces 6–7 area 1.
  // Counts: Q5 2, Q9 6, A 6, B 2.   Areas: Q5 1, Q9 5, A 5, B 1.
  // Face count: E12 = 0 (2 faces), 1 − 4/6 = 1/3 (4), 1 − 2/6 = 2/3 (2) → Σ = 8/3;
  //             E21 = 1 − 2/6 = 2/3 (2), 1/3 (4), 0 (2) → Σ = 8/3.
  //             GCEf = (8/3)/8 = 1/3; LCEf = (0 + 4·1/3 + 0)/8 = 1/6.
  // Area:       E12a = 0 (2), 1 − 4/5 = 1/5 (4), 1 − 1/5 = 4/5 (2) → Σ = 12/5;
  //             E21a = 1 − 1/5 = 4/5 (2), 1/5 (4), 0 (2) → Σ = 12/5.
  //             GCE = (12/5)/8 = 3/10; LCE = (0 + 4·1/5 + 0)/8 = 1/10.
  // Hamming by area: best per R3 segment 4 + 1 = 5 → Rm = 1/6; per Q segment 1 + 4 = 5
  //             → Rf = 1/6; HD = 1/6. (Counted in faces it would be Rm = (8 − 4 − 2)/8 = 1/4.)
  TriangleMesh m = strip();
  for (int v : {2, 3, 4, 7, 8, 9})
    m.vertices[v].x() += 2.0;
  const PsbEvaluator e(m);
  EXPECT_DOUBLE_EQ(e.totalArea(), 6.0);
  const std::vector<int> r3{0, 0, 0, 0, 0, 0, 1, 1};
  const PsbScores s = scored(e, kQ, r3);
  EXPECT_NEAR(s.GCEf, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.LCEf, 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(s.GCE, 0.3, 1e-12);
  EXPECT_NEAR(s.LCE, 0.1, 1e-12);
  EXPECT_NEAR(s.Rm, 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(s.Rf, 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(s.HD, 1.0 / 6.0, 1e-12);
}

TEST(PsbMetrics, SingleSegmentPrediction)
{
  // K1 = 1: the trivial case, all consistency errors are exactly 0. No cut: CD undefined.
  // Hamming: every P segment lies inside the one segment → Rm = 0; its best overlap is one P
  // segment of area 2 → Rf = (4 − 2)/4 = 1/2, HD = 1/4.
  // Rand: (C(8,2) + 12 − 2·12)/24 = (28 − 12)/24 = 2/3.
  const PsbEvaluator e(strip());
  const PsbScores s = scored(e, kOne, kP);
  EXPECT_EQ(s.GCE, 0.0);
  EXPECT_EQ(s.LCE, 0.0);
  EXPECT_EQ(s.GCEf, 0.0);
  EXPECT_EQ(s.LCEf, 0.0);
  EXPECT_NEAR(s.Rm, 0.0, 1e-12);
  EXPECT_NEAR(s.Rf, 0.5, 1e-12);
  EXPECT_NEAR(s.HD, 0.25, 1e-12);
  EXPECT_NEAR(s.RI, 2.0 / 3.0, 1e-12);
  EXPECT_FALSE(s.hasCD());
  EXPECT_EQ(s.cd_count, 0);
  // Neither has a cut: still undefined.
  EXPECT_FALSE(scored(e, kOne, kOne).hasCD());
}

TEST(PsbMetrics, OneSegmentPerFacePrediction)
{
  // K1 = n: trivial case, CE = 0. Rm = (4 − 2·½)/4 = 3/4, Rf = 0.
  // Rand: (0 + 12 − 0)/24 = 1/2.
  // CD: every interior edge is cut, so the cut vertices are all but t0 and b4:
  //     Z1 = {b0,b1,b2,b3,t1,t2,t3,t4}, Z_P = {b2,t2} (both in Z1, distance 0 to cut 1).
  //     Distances to P's cut {b2,t2} along edges: b0 2, b1 1, b2 0, b3 1, t1 1, t2 0, t3 1,
  //     t4 2 (the diagonal routes are 1+√2 > 2) → Σ = 8. CD = (8 + 0)/(8 + 2)/R = 0.8/R.
  const PsbEvaluator e(strip());
  const PsbScores s = scored(e, onePerFace(8), kP);
  EXPECT_EQ(s.GCE, 0.0);
  EXPECT_EQ(s.LCE, 0.0);
  EXPECT_NEAR(s.Rm, 0.75, 1e-12);
  EXPECT_NEAR(s.Rf, 0.0, 1e-12);
  EXPECT_NEAR(s.RI, 0.5, 1e-12);
  ASSERT_TRUE(s.hasCD());
  EXPECT_NEAR(s.CD, 0.8 / kStripRadius, 1e-12);
}

TEST(PsbMetrics, LabelValuesDoNotMatter)
{
  const PsbEvaluator e(strip());
  const PsbScores a = scored(e, kP, kQ);
  const PsbScores b = scored(e, {-7, -7, -7, -7, 1000000, 1000000, 1000000, 1000000}, {2, 2, 0, 0, 0, 0, 0, 0});
  EXPECT_DOUBLE_EQ(a.GCE, b.GCE);
  EXPECT_DOUBLE_EQ(a.LCE, b.LCE);
  EXPECT_DOUBLE_EQ(a.HD, b.HD);
  EXPECT_DOUBLE_EQ(a.RI, b.RI);
  EXPECT_DOUBLE_EQ(a.CD, b.CD);
}

TEST(PsbMetrics, GapsFaceRules)
{
  // The strip plus
  //   v10 at b2's position, face 8 = (b2, b3, v10): zero area, and it runs b2→b3 like face 4 =
  //     (b2, b3, t3), so GAPS gives it no neighbours (never a cut edge) — but its edges are still
  //     created, including the zero-length b2–v10;
  //   face 9 = (b0, b0, t0): a repeated index, dropped (n = 9 evaluated faces).
  // Prediction U = one segment per face (face 8 its own label), reference P (face 8 labelled 0,
  // unlike face 4 — a cut there if face 8 had neighbours).
  // Cut vertices of U: as in OneSegmentPerFacePrediction (face 8 adds none); zero set adds v10
  // (zero-length edge to b2) → |Z_U| = 9. Cut vertices of P: {b2, t2}, zero set {b2, t2, v10}.
  // Σ over Z_U of d_P: 2+1+0+1+1+0+1+2 (as before) + 0 (v10) = 8; Σ over Z_P of d_U = 0.
  // CD = 8 / (9 + 3) / R = (2/3)/R (R unchanged: face 8 has zero area).
  // Getting a rule wrong changes it: v10 unreachable → 8/10/R; face 8 with neighbours → b3 cut
  // for P → 7/13/R.
  TriangleMesh m = strip();
  m.vertices.emplace_back(2, 0, 0);
  m.faces.emplace_back(2, 3, 10);
  m.faces.emplace_back(0, 0, 5);
  const PsbEvaluator e(m);
  ASSERT_TRUE(e.ready());
  EXPECT_EQ(e.numInputFaces(), 10u);
  EXPECT_EQ(e.numEvaluatedFaces(), 9u);
  EXPECT_NEAR(e.averageRadius(), kStripRadius, 1e-12);

  std::vector<int> u = onePerFace(10);
  std::vector<int> p = kP;
  p.push_back(0);  // face 8
  p.push_back(42); // face 9: ignored
  const PsbScores s = scored(e, u, p);
  ASSERT_TRUE(s.hasCD());
  EXPECT_NEAR(s.CD, (2.0 / 3.0) / kStripRadius, 1e-12);

  // The dropped face's label changes nothing, and a GAPS-length labeling (9) is accepted.
  p.back() = 0;
  EXPECT_NEAR(scored(e, u, p).CD, s.CD, 1e-15);
  const std::vector<int> p9(p.begin(), p.begin() + 9), u9(u.begin(), u.begin() + 9);
  const PsbScores g = scored(e, u9, p9);
  EXPECT_NEAR(g.CD, s.CD, 1e-15);
  EXPECT_NEAR(g.RI, s.RI, 1e-15);
  // n = 9: U has 9 segments = n → trivial CE; Rand (0 + C(4,2) + C(5,2) − 0)/(9·4) = 16/36.
  EXPECT_EQ(s.GCE, 0.0);
  EXPECT_NEAR(s.RI, 16.0 / 36.0, 1e-12);
}

TEST(PsbMetrics, DisconnectedCutsFollowTheBenchmark)
{
  // Two separate strips: a cut in one only, the reference's cut in the other only. Every zero
  // vertex is unreachable from the other cut; the benchmark's minimum stays FLT_MAX → no CD.
  TriangleMesh a = strip(), m = strip();
  for (const Eigen::Vector3d& p : a.vertices)
    m.vertices.push_back(p + Eigen::Vector3d(0, 10, 0));
  for (const Eigen::Vector3i& f : a.faces)
    m.faces.push_back(f + Eigen::Vector3i::Constant(10));
  const PsbEvaluator e(m);
  std::vector<int> s1 = kP, s2(8, 0);
  s1.insert(s1.end(), 8, 0);
  s2.insert(s2.end(), kP.begin(), kP.end());
  EXPECT_FALSE(scored(e, s1, s2).hasCD());
  // Cuts in both components for S1, one for S2: the reachable part is finite, the unreachable
  // vertices add FLT_MAX each, as the benchmark does — an enormous CD, not a small one.
  for (int f = 8; f < 16; ++f)
    s1[f] = kP[f - 8] + 2;
  const PsbScores s = scored(e, s1, s2);
  ASSERT_TRUE(s.hasCD());
  EXPECT_GT(s.CD, 1e37);
}

TEST(PsbMetrics, MeanOverHumans)
{
  // P against {P, Q, one segment}: CD 0, 1/R, undefined → mean over the two that exist = ½/R.
  // GCE 0, 1/4, 0 → 1/12. Rm 0, 1/4, and vs one segment: (4 − 2)/4 = 1/2 → 1/4.
  // Rf 0, 1/4, 0 → 1/12.
  const PsbEvaluator e(strip());
  PsbScores mean;
  std::vector<PsbScores> each;
  ASSERT_TRUE(e.scoreAgainstAll(kP, {kP, kQ, kOne}, mean, &each));
  ASSERT_EQ(each.size(), 3u);
  EXPECT_FALSE(each[2].hasCD());
  EXPECT_EQ(mean.count, 3);
  EXPECT_EQ(mean.cd_count, 2);
  EXPECT_NEAR(mean.CD, 0.5 / kStripRadius, 1e-12);
  EXPECT_NEAR(mean.GCE, 1.0 / 12.0, 1e-12);
  EXPECT_NEAR(mean.Rm, 0.25, 1e-12);
  EXPECT_NEAR(mean.Rf, 1.0 / 12.0, 1e-12);

  // Averaging scores that all lack CD keeps CD undefined.
  const PsbScores none = averagePsbScores({each[2], each[2]});
  EXPECT_FALSE(none.hasCD());
  EXPECT_EQ(none.count, 2);
  EXPECT_EQ(averagePsbScores({}).count, 0);
}

TEST(PsbMetrics, BadInputIsRejectedWithoutThrowing)
{
  PsbEvaluator e;
  PsbScores s;
  EXPECT_FALSE(e.ready());
  EXPECT_FALSE(e.score(kP, kP, s)); // no mesh
  EXPECT_FALSE(e.setInputMesh(TriangleMesh()));
  TriangleMesh bad = strip();
  bad.faces[3] = Eigen::Vector3i(0, 1, 99);
  EXPECT_FALSE(e.setInputMesh(bad));
  bad = strip();
  bad.vertices[0].x() = std::nan("");
  EXPECT_FALSE(e.setInputMesh(bad));
  TriangleMesh flat({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}); // zero area
  EXPECT_FALSE(e.setInputMesh(flat));

  ASSERT_TRUE(e.setInputMesh(strip()));
  EXPECT_FALSE(e.score({0, 1}, kP, s)); // wrong length
  EXPECT_EQ(s.count, 0);
  EXPECT_FALSE(e.scoreAgainstAll(kP, {}, s));
  EXPECT_FALSE(e.scoreAgainstAll(kP, {kP, {1, 2, 3}}, s));
  // The convenience function reports failure as an empty score.
  EXPECT_EQ(evaluateSegmentation(strip(), kP, {0}).count, 0);
  EXPECT_EQ(evaluateSegmentation(strip(), kP, kQ).count, 1);
}
