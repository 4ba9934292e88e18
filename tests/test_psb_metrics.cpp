// Princeton Segmentation Benchmark metrics: hand-worked cases on a small strip, then the
// fixture table of /work/shared/notes/psb-metrics.md on the psb-dev models.
#include <segmat/evaluation/psb_benchmark.h>
#include <segmat/evaluation/psb_metrics.h>
#include <segmat/io/off.h>

#include <util/temp_files.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <string>
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

// Every column at once, in the fixture's order plus LCEf; a NaN \a cd means "undefined".
void
expectScores(const PsbScores& s, double cd, double hd, double rm, double rf, double ri,
             double gce, double lce, double gcef, double lcef)
{
  if (std::isnan(cd))
    EXPECT_FALSE(s.hasCD()) << s.CD;
  else
    EXPECT_NEAR(s.CD, cd, 1e-12);
  const double got[8] = {s.HD, s.Rm, s.Rf, s.RI, s.GCE, s.LCE, s.GCEf, s.LCEf};
  const double want[8] = {hd, rm, rf, ri, gce, lce, gcef, lcef};
  const char* names[8] = {"HD", "Rm", "Rf", "RI", "GCE", "LCE", "GCEf", "LCEf"};
  for (int c = 0; c < 8; ++c)
    EXPECT_NEAR(got[c], want[c], 1e-12) << names[c];
}

const double kUndefined = std::nan("");

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
  ASSERT_TRUE(s.hasCD()); // both have a cut: CD is defined, and 0
  expectScores(s, 0, 0, 0, 0, 0, 0, 0, 0, 0);
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
  expectScores(s, 1.0 / kStripRadius, 0.25, 0.25, 0.25, 0.5, 0.25, 0.125, 0.25, 0.125);

  // Swapping the two changes nothing here (Rm = Rf); see SingleSegmentPrediction for Rm ≠ Rf.
  expectScores(scored(e, kQ, kP), 1.0 / kStripRadius, 0.25, 0.25, 0.25, 0.5, 0.25, 0.125, 0.25,
               0.125);
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
  expectScores(s, kUndefined, 0.25, 0.0, 0.5, 2.0 / 3.0, 0, 0, 0, 0);
  // Swapped (P predicted, one segment as truth): Rm and Rf swap, nothing else changes.
  expectScores(scored(e, kP, kOne), kUndefined, 0.25, 0.5, 0.0, 2.0 / 3.0, 0, 0, 0, 0);
  EXPECT_EQ(s.cd_count, 0);
  // Neither has a cut: still undefined.
  EXPECT_FALSE(scored(e, kOne, kOne).hasCD());
}

TEST(PsbMetrics, OneSegmentPerFacePrediction)
{
  // K1 = n: trivial case, CE = 0. Rm = (4 − 2·½)/4 = 3/4, Rf = 0, HD = 3/8.
  // Rand: (0 + 12 − 0)/24 = 1/2.
  // CD: every interior edge is cut, so the cut vertices are all but t0 and b4:
  //     Z1 = {b0,b1,b2,b3,t1,t2,t3,t4}, Z_P = {b2,t2} (both in Z1, distance 0 to cut 1).
  //     Distances to P's cut {b2,t2} along edges: b0 2, b1 1, b2 0, b3 1, t1 1, t2 0, t3 1,
  //     t4 2 (the diagonal routes are 1+√2 > 2) → Σ = 8. CD = (8 + 0)/(8 + 2)/R = 0.8/R.
  const PsbEvaluator e(strip());
  const PsbScores s = scored(e, onePerFace(8), kP);
  expectScores(s, 0.8 / kStripRadius, 0.375, 0.75, 0.0, 0.5, 0, 0, 0, 0);
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

TEST(PsbMetrics, FlippedFaceHasNoNeighbours)
{
  // Square 0=(0,0) 1=(1,0) 2=(1,1) 3=(0,1) plus 4=(−1,½). Face 0 = (0,1,2) runs 2→0; face 1 =
  // (0,3,2) is flipped and runs 2→0 too, so GAPS makes it on fresh vertices: no neighbours.
  // Face 2 = (3,0,4) runs 3→0, which face 1 would have paired with (it runs 0→3).
  // Labels {0,1,0} differ across both of face 1's edges, yet no edge has a face on each side:
  // no cut at all, so CD is undefined even for identical segmentations. With face 1 wound
  // (0,2,3) like its neighbours, both edges are cuts and identical labelings give CD = 0.
  std::vector<Eigen::Vector3d> v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}};
  const std::vector<int> labels{0, 1, 0};
  const PsbEvaluator flipped(TriangleMesh(v, {{0, 1, 2}, {0, 3, 2}, {3, 0, 4}}));
  EXPECT_FALSE(scored(flipped, labels, labels).hasCD());
  const PsbEvaluator oriented(TriangleMesh(v, {{0, 1, 2}, {0, 2, 3}, {3, 0, 4}}));
  const PsbScores s = scored(oriented, labels, labels);
  ASSERT_TRUE(s.hasCD());
  EXPECT_EQ(s.CD, 0.0);
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

// ---------------------------------------------------------------------------------------------
// Fixture of psb-metrics.md: on every psb-dev model, human #0 (N_0.seg) as the prediction against
// all of that model's humans (itself included). Columns CD HD Rm Rf RI GCE LCE GCEf; the table is
// printed to 6 decimals by an implementation that matches the official binary, so each cell must
// agree within half a unit of the 6th decimal (plus rounding slack).

namespace {

struct FixtureRow
{
  int model;
  int humans;
  double v[8]; // CD HD Rm Rf RI GCE LCE GCEf
};

const FixtureRow kFixture[] = {
    {1, 16, {0.209811, 0.179187, 0.199841, 0.158533, 0.082521, 0.157431, 0.097272, 0.163540}},
    {6, 14, {0.173953, 0.166617, 0.116735, 0.216498, 0.092515, 0.153507, 0.079908, 0.172002}},
    {21, 15, {0.282548, 0.053240, 0.009601, 0.096880, 0.101855, 0.020142, 0.014434, 0.019424}},
    {26, 10, {0.029161, 0.004446, 0.004446, 0.004446, 0.014523, 0.011886, 0.008629, 0.013759}},
    {41, 12, {0.153034, 0.052655, 0.064890, 0.040419, 0.052917, 0.011585, 0.009087, 0.011118}},
    {46, 10, {0.104704, 0.039772, 0.040875, 0.038669, 0.035045, 0.020988, 0.012970, 0.019733}},
    {61, 14, {0.092230, 0.171290, 0.092536, 0.250043, 0.185037, 0.121133, 0.066884, 0.120172}},
    {66, 12, {0.084553, 0.088467, 0.068521, 0.108412, 0.063057, 0.079575, 0.052120, 0.077600}},
    {81, 12, {0.047989, 0.034371, 0.019759, 0.048982, 0.009630, 0.033857, 0.023937, 0.033356}},
    {86, 11, {0.057848, 0.040692, 0.017945, 0.063440, 0.009900, 0.032200, 0.021838, 0.030476}},
    {101, 15, {0.079962, 0.035968, 0.025455, 0.046480, 0.033217, 0.032201, 0.020747, 0.030784}},
    {106, 9, {0.062060, 0.029295, 0.032990, 0.025600, 0.026476, 0.044572, 0.025439, 0.042374}},
    {121, 9, {0.031028, 0.020716, 0.014963, 0.026468, 0.014628, 0.025666, 0.019090, 0.024403}},
    {126, 13, {0.068173, 0.029519, 0.021662, 0.037375, 0.014128, 0.035172, 0.021392, 0.034845}},
    {141, 14, {0.380040, 0.066591, 0.057988, 0.075194, 0.131901, 0.024906, 0.019274, 0.025172}},
    {146, 10, {0.301613, 0.115855, 0.015048, 0.216662, 0.176139, 0.027877, 0.022460, 0.028363}},
    {161, 14, {0.025236, 0.024351, 0.031282, 0.017420, 0.027222, 0.033665, 0.025370, 0.033197}},
    {166, 13, {0.111403, 0.059289, 0.085050, 0.033528, 0.069246, 0.059771, 0.030845, 0.058600}},
    {181, 13, {0.184726, 0.129246, 0.150045, 0.108448, 0.122876, 0.109327, 0.061083, 0.108060}},
    {186, 12, {0.184407, 0.203685, 0.201992, 0.205378, 0.131398, 0.230552, 0.134888, 0.229855}},
    {201, 13, {0.074642, 0.058317, 0.063649, 0.052986, 0.037907, 0.069629, 0.046878, 0.069421}},
    {206, 11, {0.065701, 0.066661, 0.072442, 0.060881, 0.032334, 0.081273, 0.056516, 0.080888}},
    {221, 11, {0.115119, 0.053240, 0.015586, 0.090894, 0.116400, 0.029386, 0.020854, 0.028227}},
    {226, 9, {0.172575, 0.196821, 0.303915, 0.089727, 0.281501, 0.090799, 0.062700, 0.088044}},
    {241, 12, {0.067304, 0.046079, 0.045825, 0.046332, 0.036450, 0.061610, 0.038343, 0.060192}},
    {246, 7, {0.042613, 0.044756, 0.057271, 0.032240, 0.024486, 0.050346, 0.034316, 0.049354}},
    {281, 6, {0.217744, 0.220779, 0.017122, 0.424436, 0.094745, 0.033772, 0.031519, 0.033819}},
    {286, 10, {0.088749, 0.110969, 0.081043, 0.140895, 0.054309, 0.077324, 0.056919, 0.077277}},
    {301, 10, {0.086158, 0.099105, 0.133321, 0.064889, 0.096073, 0.094805, 0.063052, 0.098307}},
    {306, 10, {0.229034, 0.100047, 0.096547, 0.103546, 0.122448, 0.090844, 0.062074, 0.090845}},
    {321, 11, {0.019663, 0.005687, 0.001895, 0.009479, 0.008745, 0.004903, 0.003034, 0.005872}},
    {326, 12, {0.078398, 0.028211, 0.000051, 0.056371, 0.051252, 0.000211, 0.000176, 0.000327}},
    {341, 14, {0.097256, 0.037024, 0.020985, 0.053063, 0.030793, 0.000045, 0.000045, 0.000043}},
    {346, 11, {0.004161, 0.001707, 0.000767, 0.002647, 0.004949, 0.002280, 0.001570, 0.003080}},
    {361, 10, {0.102298, 0.091442, 0.082126, 0.100758, 0.101461, 0.104391, 0.061937, 0.107363}},
    {366, 12, {0.368879, 0.099168, 0.079987, 0.118349, 0.189705, 0.052608, 0.034604, 0.053048}},
    {381, 13, {0.227528, 0.148168, 0.076387, 0.219950, 0.230584, 0.110879, 0.064588, 0.111067}},
    {386, 13, {0.161622, 0.168762, 0.142306, 0.195218, 0.120071, 0.191348, 0.110848, 0.186140}},
};
const double kFixtureMean[8] = {0.128524, 0.082163, 0.067443, 0.096883,
                                0.079696, 0.063486, 0.039938, 0.063688};
const char* const kColumns[8] = {"CD", "HD", "Rm", "Rf", "RI", "GCE", "LCE", "GCEf"};

const std::string kPsbDev = std::string(SEGMAT_SHARED_DATA_DIR) + "/psb-dev";

} // namespace

TEST(PsbMetricsFixture, HumanZeroAgainstAllHumansOnPsbDev)
{
  if (!test::fileExists(kPsbDev + "/off/1.off"))
    GTEST_SKIP() << "no " << kPsbDev;
  const double tolerance = 6e-7;
  std::vector<PsbScores> per_model;
  for (const FixtureRow& row : kFixture) {
    SCOPED_TRACE("model " + std::to_string(row.model));
    const PsbEvaluator evaluator(io::loadOff(kPsbDev + "/off/" + std::to_string(row.model) + ".off"));
    ASSERT_TRUE(evaluator.ready());
    const std::vector<std::string> paths = psbHumanSegmentationPaths(kPsbDev, row.model);
    ASSERT_EQ(static_cast<int>(paths.size()), row.humans);
    std::vector<std::vector<int>> humans;
    for (const std::string& p : paths)
      humans.push_back(loadLabelsFor(evaluator, p));
    PsbScores s;
    ASSERT_TRUE(evaluator.scoreAgainstAll(humans[0], humans, s));
    EXPECT_EQ(s.count, row.humans);
    EXPECT_EQ(s.cd_count, row.humans);
    const double got[8] = {s.CD, s.HD, s.Rm, s.Rf, s.RI, s.GCE, s.LCE, s.GCEf};
    for (int c = 0; c < 8; ++c)
      EXPECT_NEAR(got[c], row.v[c], tolerance) << kColumns[c];
    per_model.push_back(s);
  }
  const PsbScores mean = averagePsbScores(per_model);
  EXPECT_EQ(mean.count, 38);
  const double got[8] = {mean.CD, mean.HD, mean.Rm, mean.Rf, mean.RI, mean.GCE, mean.LCE, mean.GCEf};
  for (int c = 0; c < 8; ++c)
    EXPECT_NEAR(got[c], kFixtureMean[c], tolerance) << "mean " << kColumns[c];
}
