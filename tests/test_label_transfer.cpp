// Face orientation, the transfer's energy terms and the mesh / cloud transfers on hand-built shapes.
#include <segmat/geometry/face_orientation.h>
#include <segmat/segmentation/label_transfer.h>

#include <gtest/gtest.h>
#include <pcl/console/print.h>

#include <cmath>
#include <map>
#include <random>
#include <tuple>

using namespace segmat;

namespace {

// Closed box [lo, hi] with n[a] cells along axis a, wound outward (counter-clockwise seen from
// outside).
TriangleMesh
boxMesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Vector3i& n)
{
  TriangleMesh mesh;
  std::map<std::tuple<int, int, int>, int> index;
  const auto vertex = [&](Eigen::Vector3i g) {
    const auto key = std::make_tuple(g[0], g[1], g[2]);
    auto it = index.find(key);
    if (it != index.end())
      return it->second;
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a)
      p[a] = lo[a] + (hi[a] - lo[a]) * g[a] / n[a];
    mesh.vertices.push_back(p);
    return index[key] = static_cast<int>(mesh.vertices.size()) - 1;
  };
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < n[u]; ++i)
        for (int j = 0; j < n[v]; ++j) {
          Eigen::Vector3i g00, g10, g11, g01;
          g00[a] = g10[a] = g11[a] = g01[a] = side * n[a];
          g00[u] = i, g00[v] = j;
          g10[u] = i + 1, g10[v] = j;
          g11[u] = i + 1, g11[v] = j + 1;
          g01[u] = i, g01[v] = j + 1;
          const int p00 = vertex(g00), p10 = vertex(g10), p11 = vertex(g11), p01 = vertex(g01);
          if (side == 1) { // (u, v, a) is right-handed: counter-clockwise in (u, v) faces +a
            mesh.faces.emplace_back(p00, p10, p11);
            mesh.faces.emplace_back(p00, p11, p01);
          }
          else {
            mesh.faces.emplace_back(p00, p11, p10);
            mesh.faces.emplace_back(p00, p01, p11);
          }
        }
  }
  return mesh;
}

// Closed L-shaped prism: profile (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), z in [0, 1]. One concave
// vertical edge at (1,1).
TriangleMesh
lPrism()
{
  const std::vector<Eigen::Vector2d> p{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  TriangleMesh mesh;
  for (int z = 0; z < 2; ++z)
    for (const auto& q : p)
      mesh.vertices.emplace_back(q.x(), q.y(), z);
  const int top = 6;
  for (int t : {1, 2, 3, 4}) { // fan from vertex 0 over the L (it is star-shaped from (0,0))
    mesh.faces.emplace_back(top + 0, top + t, top + t + 1);
    mesh.faces.emplace_back(0, t + 1, t);
  }
  for (int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    mesh.faces.emplace_back(i, j, top + j);
    mesh.faces.emplace_back(i, top + j, top + i);
  }
  return mesh;
}

// Medial "graph" of lone spheres (one Point node each, no edges needed for the transfer).
MatGraph::ConstPtr
sphereGraph(const std::vector<Eigen::Vector3d>& centers, const std::vector<double>& radii)
{
  std::vector<MatNode> nodes(centers.size());
  for (std::size_t i = 0; i < centers.size(); ++i) {
    nodes[i].kind = MatNodeKind::Point;
    nodes[i].v = Eigen::Vector3i(static_cast<int>(i), -1, -1);
    nodes[i].mean_radius = radii[i];
    nodes[i].centroid = centers[i];
    nodes[i].normal = Eigen::Vector3d::Zero();
  }
  return std::make_shared<MatGraph>(centers, radii, nodes,
                                    std::vector<std::vector<int>>(centers.size()));
}

// The bar's six axis spheres (nodes 0–5) and a lone small sphere near the +x end cap's corner
// (node 6).
MatGraph::ConstPtr
barWithCornerSphere()
{
  return sphereGraph({{-1.5, 0, 0}, {-1, 0, 0}, {-0.5, 0, 0}, {0.5, 0, 0}, {1, 0, 0},
                      {1.5, 0, 0}, {1.9, 0.4, 0.4}},
                     {0.4, 0.4, 0.4, 0.4, 0.4, 0.4, 0.05});
}

// Box along x, [-2, 2] × [-0.5, 0.5]², and six spheres on its axis: three left, three right.
struct BarScene
{
  TriangleMesh::Ptr mesh;
  MatGraph::ConstPtr graph;
  std::vector<std::vector<int>> parts{{0, 1, 2}, {3, 4, 5}};
};

BarScene
bar()
{
  BarScene s;
  s.mesh = std::make_shared<TriangleMesh>(
      boxMesh({-2, -0.5, -0.5}, {2, 0.5, 0.5}, Eigen::Vector3i(8, 2, 2)));
  s.graph = sphereGraph({{-1.5, 0, 0}, {-1, 0, 0}, {-0.5, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1.5, 0, 0}},
                        std::vector<double>(6, 0.4));
  return s;
}

std::vector<int>
labelsBySide(const TriangleMesh& mesh)
{
  std::vector<int> expected(mesh.numFaces());
  for (std::size_t f = 0; f < mesh.numFaces(); ++f)
    expected[f] = mesh.faceCentroid(static_cast<int>(f)).x() > 0.0 ? 1 : 0;
  return expected;
}

} // namespace

TEST(FaceOrientation, RepairsFlippedFacesAndInvertedMeshes)
{
  TriangleMesh mesh = boxMesh({0, 0, 0}, {1, 2, 3}, Eigen::Vector3i(3, 2, 4));
  const Eigen::Vector3d centre(0.5, 1, 1.5);
  const auto outward = [&](const TriangleMesh& m, const std::vector<int>& signs) {
    for (std::size_t f = 0; f < m.numFaces(); ++f) {
      const Eigen::Vector3d n = signs[f] * m.faceNormal(static_cast<int>(f));
      if (n.dot(m.faceCentroid(static_cast<int>(f)) - centre) <= 0.0)
        return false;
    }
    return true;
  };
  EXPECT_EQ(computeOutwardFaceSigns(mesh, mesh.faceAdjacency()),
            std::vector<int>(mesh.numFaces(), 1));
  // Flip every third face and, separately, the whole mesh.
  for (std::size_t f = 0; f < mesh.numFaces(); f += 3)
    std::swap(mesh.faces[f][1], mesh.faces[f][2]);
  std::vector<int> signs = computeOutwardFaceSigns(mesh, mesh.faceAdjacency());
  EXPECT_TRUE(outward(mesh, signs));
  for (std::size_t f = 0; f < mesh.numFaces(); ++f)
    EXPECT_EQ(signs[f], f % 3 == 0 ? -1 : 1);
  for (auto& t : mesh.faces)
    std::swap(t[1], t[2]);
  EXPECT_TRUE(outward(mesh, computeOutwardFaceSigns(mesh, mesh.faceAdjacency())));
  // A NaN vertex does not spoil the orientation of the finite faces of its component.
  mesh.vertices[0] = Eigen::Vector3d::Constant(std::nan(""));
  signs = computeOutwardFaceSigns(mesh, mesh.faceAdjacency());
  for (std::size_t f = 0; f < mesh.numFaces(); ++f) {
    const Eigen::Vector3d n = signs[f] * mesh.faceNormal(static_cast<int>(f));
    if (n.allFinite() && mesh.faceCentroid(static_cast<int>(f)).allFinite())
      EXPECT_GT(n.dot(mesh.faceCentroid(static_cast<int>(f)) - centre), 0.0) << f;
  }
}

TEST(FaceOrientation, ComponentsDegenerateAndEmpty)
{
  // Two boxes, one wound inward, plus a degenerate face: each component on its own.
  TriangleMesh a = boxMesh({0, 0, 0}, {1, 1, 1}, Eigen::Vector3i(1, 1, 1));
  TriangleMesh b = boxMesh({3, 0, 0}, {4, 1, 1}, Eigen::Vector3i(1, 1, 1));
  const int offset = static_cast<int>(a.vertices.size());
  for (auto v : b.vertices)
    a.vertices.push_back(v);
  for (auto t : b.faces)
    a.faces.emplace_back(t[0] + offset, t[2] + offset, t[1] + offset);
  a.faces.emplace_back(0, 0, 1);
  const std::vector<int> signs = computeOutwardFaceSigns(a, a.faceAdjacency());
  ASSERT_EQ(signs.size(), 25u);
  for (int f = 0; f < 12; ++f)
    EXPECT_EQ(signs[f], 1);
  for (int f = 12; f < 24; ++f)
    EXPECT_EQ(signs[f], -1);
  EXPECT_EQ(signs[24], 1);
  EXPECT_TRUE(computeOutwardFaceSigns(TriangleMesh(), {}).empty());
}

TEST(LabelTransferTerms, CreaseCostsByHand)
{
  // ω = 0.3: concave 90° → 2·⌊0.3·90/180·1e5⌋ = 30000; convex 90° → 2·45000; flat → 2·60000.
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();
  // Floor (normal +z) at the origin, wall (normal −x) to its +x side rising up: a valley.
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, 1}, -x, 0.3), 30000.0);
  // Floor and a wall falling away (normal +x): a ridge.
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, -1}, x, 0.3), 90000.0);
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, 0}, z, 0.3), 120000.0);
  // Symmetric in a and b; scales with ω; no NaN from zero or NaN normals.
  EXPECT_EQ(computeCreaseCost({1, 0, 1}, -x, {0, 0, 0}, z, 0.3), 30000.0);
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, 0}, z, 0.15), 60000.0);
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, Eigen::Vector3d::Zero(), {1, 0, 0}, z, 0.3), 90000.0);
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, Eigen::Vector3d::Constant(std::nan("")), {1, 0, 0}, z,
                              0.3),
            90000.0);
}

TEST(LabelTransferTerms, SharpConcaveCreaseCostsByHand)
{
  // CreaseModel::SharpConcave, ω = 0.3: concave θ → 2·⌊0.6·exp(−θ/10°)·1e5⌋; convex and flat as
  // the reference.
  const auto sharp = CreaseModel::SharpConcave;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();
  // 90° valley: 0.6·e^−9·1e5 = 7.40 → 2·7 (the reference: 30000).
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, 1}, -x, 0.3, sharp), 14.0);
  EXPECT_EQ(computeCreaseCost({1, 0, 1}, -x, {0, 0, 0}, z, 0.3, sharp), 14.0);
  // 10° valley (the +x face tilts its normal towards −x): 0.6·e^−1·1e5 = 22072.77 → 2·22072
  // (the reference: 2·⌊0.3·170/180·1e5⌋ = 56666).
  const double t = 10.0 * 3.14159265358979323846 / 180.0;
  const Eigen::Vector3d tilted(-std::sin(t), 0.0, std::cos(t));
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, 0.1}, tilted, 0.3, sharp), 44144.0);
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, 0.1}, tilted, 0.3), 56666.0);
  // No jump at θ = 0: a 0.01° valley costs what a flat edge costs, less the round-off of e^−0.001.
  const double u = 0.01 * 3.14159265358979323846 / 180.0;
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, 0}, Eigen::Vector3d(-std::sin(u), 0.0, std::cos(u)),
                              0.3, sharp),
            2.0 * std::floor(60000.0 * std::exp(-0.001)));
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, -1}, x, 0.3, sharp), 90000.0);
  EXPECT_EQ(computeCreaseCost({0, 0, 0}, z, {1, 0, 0}, z, 0.3, sharp), 120000.0);
}

TEST(LabelTransferTerms, MeshSmoothnessOnAnLPrism)
{
  TriangleMesh mesh = lPrism();
  // Wind a few faces the wrong way: orientation repair must make no difference.
  std::swap(mesh.faces[0][1], mesh.faces[0][2]);
  std::swap(mesh.faces[9][1], mesh.faces[9][2]);
  const std::vector<PottsEdge> edges = computeMeshSmoothnessEdges(mesh, 0.3);
  ASSERT_EQ(edges.size(), 30u); // 20 faces, closed: 3·20/2 edges
  int concave = 0, convex = 0, flat = 0;
  for (const PottsEdge& e : edges) {
    if (e.weight == 30000.0)
      ++concave;
    else if (e.weight == 90000.0)
      ++convex;
    else if (e.weight == 120000.0)
      ++flat;
  }
  // One concave vertical edge (the inner corner), five convex vertical ones, 12 cap rims; flat:
  // 6 side-quad diagonals and 3 + 3 fan diagonals in the caps.
  EXPECT_EQ(concave, 1);
  EXPECT_EQ(convex, 17);
  EXPECT_EQ(flat, 12);
  // The sharp-concave model changes only the concave edge (90°: 14, see above).
  const std::vector<PottsEdge> sharp =
      computeMeshSmoothnessEdges(mesh, 0.3, CreaseModel::SharpConcave);
  ASSERT_EQ(sharp.size(), edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k)
    EXPECT_EQ(sharp[k].weight, edges[k].weight == 30000.0 ? 14.0 : edges[k].weight) << k;
}

TEST(LabelTransferTerms, PartDistanceCostsMatchBruteForce)
{
  std::mt19937 rng(99u);
  const auto unit = [&] { return static_cast<double>(rng()) / 4294967296.0; };
  std::vector<Eigen::Vector3d> centers(60);
  std::vector<double> radii(60);
  for (int i = 0; i < 60; ++i) {
    centers[i] = Eigen::Vector3d(unit(), unit(), unit()) * 2.0;
    radii[i] = 0.2 * unit();
  }
  // Slab nodes over sphere triples, cone nodes over pairs.
  std::vector<MatNode> nodes;
  for (int i = 0; i + 2 < 60; i += 3) {
    MatNode n;
    n.kind = i % 2 ? MatNodeKind::Cone : MatNodeKind::Slab;
    n.v = Eigen::Vector3i(i, i + 1, n.kind == MatNodeKind::Slab ? i + 2 : -1);
    n.centroid = centers[i];
    n.normal = Eigen::Vector3d::Zero();
    nodes.push_back(n);
  }
  const MatGraph graph(centers, radii, nodes, std::vector<std::vector<int>>(nodes.size()));
  const std::vector<std::vector<int>> parts{{0, 1, 2, 3}, {4, 5, 6, 7, 8, 9}, {10, 11}, {}};
  std::vector<Eigen::Vector3d> queries(200);
  for (auto& q : queries)
    q = Eigen::Vector3d(unit(), unit(), unit()) * 3.0 - Eigen::Vector3d::Constant(0.5);
  const Eigen::MatrixXd costs = computePartDistanceCosts(queries, graph, parts);
  ASSERT_EQ(costs.rows(), 200);
  ASSERT_EQ(costs.cols(), 4);
  const double diagonal = graph.centerBoundingBoxDiagonal();
  for (int i = 0; i < 200; ++i)
    for (int l = 0; l < 3; ++l) {
      double best = 1e300;
      for (int node : parts[l])
        for (int k = 0; k < nodes[node].size(); ++k) {
          const int s = nodes[node].v[k];
          best = std::min(best, (queries[i] - centers[s]).norm() - radii[s]);
        }
      EXPECT_EQ(costs(i, l), std::floor(std::max(0.0, best) / diagonal * 1e5)) << i << " " << l;
    }
  EXPECT_EQ(costs(0, 3), 1e9); // a part without spheres never wins
  // The same costs on any number of threads.
  EXPECT_EQ(computePartDistanceCosts(queries, graph, parts, 1), costs);
  EXPECT_EQ(computePartDistanceCosts(queries, graph, parts, 3), costs);
  // A non-finite position has no preference.
  const Eigen::MatrixXd nan_costs = computePartDistanceCosts(
      {Eigen::Vector3d(std::nan(""), 0, 0), queries[0]}, graph, parts);
  EXPECT_EQ(nan_costs.row(0), Eigen::RowVector4d(0, 0, 0, 1e9)); // the empty part still never wins
  EXPECT_EQ(nan_costs.row(1), costs.row(0));
}

TEST(LabelTransferTerms, CompactLabels)
{
  std::vector<int> labels{5, 2, 5, -1, 9, 2};
  EXPECT_EQ(compactLabels(labels), 3);
  EXPECT_EQ(labels, (std::vector<int>{1, 0, 1, -1, 2, 0}));
  std::vector<int> none;
  EXPECT_EQ(compactLabels(none), 0);
}

TEST(MeshLabelTransfer, BarSplitsAtTheMiddle)
{
  BarScene s = bar();
  MeshLabelTransfer transfer;
  transfer.setJoinFlatBoundaries(false); // the cut alone (the halves meet on flat faces)
  transfer.setInputMesh(s.mesh);
  transfer.setInputGraph(s.graph);
  transfer.setParts(s.parts);
  std::vector<int> labels;
  ASSERT_TRUE(transfer.transfer(labels));
  EXPECT_EQ(labels, labelsBySide(*s.mesh));
  EXPECT_GT(transfer.getEnergy(), 0.0);

  // The same with half the faces wound the wrong way, and with the parts given in the other
  // order (labels follow part order).
  auto flipped = std::make_shared<TriangleMesh>(*s.mesh);
  for (std::size_t f = 0; f < flipped->numFaces(); f += 2)
    std::swap(flipped->faces[f][0], flipped->faces[f][1]);
  transfer.setInputMesh(flipped);
  transfer.setParts({s.parts[1], s.parts[0]});
  ASSERT_TRUE(transfer.transfer(labels));
  std::vector<int> expected = labelsBySide(*s.mesh);
  for (int& l : expected)
    l = 1 - l;
  EXPECT_EQ(labels, expected);

  // By default the halves are joined: their boundary runs across the bar's four flat sides.
  transfer.setJoinFlatBoundaries(true);
  ASSERT_TRUE(transfer.transfer(labels));
  EXPECT_EQ(labels, std::vector<int>(s.mesh->numFaces(), 0));
  EXPECT_EQ(transfer.getLabelParts(), (std::vector<std::vector<int>>{{0, 1}}));
}

TEST(MeshLabelTransfer, LargeMeshIsCutCoarseToFineAlongTheSameBoundary)
{
  BarScene s = bar();
  s.mesh = std::make_shared<TriangleMesh>(
      boxMesh({-2, -0.5, -0.5}, {2, 0.5, 0.5}, Eigen::Vector3i(32, 8, 8))); // 2304 faces
  MeshLabelTransfer transfer;
  EXPECT_EQ(transfer.getMaxFullCutElements(), 65536u);
  transfer.setJoinFlatBoundaries(false);
  transfer.setInputMesh(s.mesh);
  transfer.setInputGraph(s.graph);
  transfer.setParts(s.parts);
  std::vector<int> whole, coarse;
  ASSERT_TRUE(transfer.transfer(whole));
  const double whole_energy = transfer.getEnergy();
  // 250 clusters of about 10 faces: x = 0 is no cluster's border, and the fine pass finds it.
  transfer.setMaxFullCutElements(500);
  ASSERT_TRUE(transfer.transfer(coarse));
  EXPECT_EQ(coarse, labelsBySide(*s.mesh));
  EXPECT_EQ(coarse, whole);
  EXPECT_EQ(transfer.getEnergy(), whole_energy);
}

TEST(MeshLabelTransfer, SmoothingOverridesAWeakDataPreference)
{
  // Part 1 is a lone small sphere near the +x end cap's corner: without smoothing a few faces
  // near it take label 1; with ω = 0.3 cutting them out costs more than it saves, and every
  // face takes part 0 — so label 1 disappears and the labels are compacted to all 0.
  BarScene s = bar();
  MeshLabelTransfer transfer;
  transfer.setJoinFlatBoundaries(false); // the cut alone (the halves meet on flat faces)
  transfer.setInputMesh(s.mesh);
  transfer.setInputGraph(barWithCornerSphere());
  transfer.setParts({{0, 1, 2, 3, 4, 5}, {6}});
  transfer.setSmoothnessWeight(0.0);
  transfer.setMinPartFraction(0.0); // the smoothness alone (the minimal share: next test)
  std::vector<int> labels;
  ASSERT_TRUE(transfer.transfer(labels));
  int ones = 0;
  for (int l : labels)
    ones += l == 1;
  EXPECT_GT(ones, 0);
  transfer.setSmoothnessWeight(0.3);
  ASSERT_TRUE(transfer.transfer(labels));
  EXPECT_EQ(labels, std::vector<int>(s.mesh->numFaces(), 0));
}

// The same lone small sphere as a third part, without smoothing: it wins the faces at one
// corner of the bar. A minimal share below that corner's share keeps the part; one above it
// drops the part and cuts again, and the faces then split by side, as with the two bar parts
// alone.
TEST(MeshLabelTransfer, PartBelowTheMinimalShareIsDropped)
{
  EXPECT_DOUBLE_EQ(MeshLabelTransfer().getMinPartFraction(), 0.002); // the default
  BarScene s = bar();
  MeshLabelTransfer transfer;
  transfer.setJoinFlatBoundaries(false); // the cut alone (the halves meet on flat faces)
  transfer.setInputMesh(s.mesh);
  transfer.setInputGraph(barWithCornerSphere());
  transfer.setParts({{0, 1, 2}, {3, 4, 5}, {6}});
  transfer.setSmoothnessWeight(0.0);
  transfer.setMinPartFraction(0.0);
  std::vector<int> labels;
  ASSERT_TRUE(transfer.transfer(labels));
  double corner = 0.0, total = 0.0;
  for (std::size_t f = 0; f < labels.size(); ++f) {
    total += s.mesh->faceArea(int(f));
    if (labels[f] == 2)
      corner += s.mesh->faceArea(int(f));
  }
  ASSERT_GT(corner, 0.0);
  const double share = corner / total;
  ASSERT_LT(share, 0.5);
  const std::vector<int> all = labels;

  transfer.setMinPartFraction(0.5 * share);
  ASSERT_TRUE(transfer.transfer(labels));
  EXPECT_EQ(labels, all);
  EXPECT_EQ(transfer.getLabelParts(), (std::vector<std::vector<int>>{{0}, {1}, {2}}));

  transfer.setMinPartFraction(2.0 * share);
  ASSERT_TRUE(transfer.transfer(labels));
  EXPECT_EQ(labels, labelsBySide(*s.mesh));
  EXPECT_EQ(transfer.getLabelParts(), (std::vector<std::vector<int>>{{0}, {1}}));
}

TEST(MeshLabelTransfer, OnePartAndBadInput)
{
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  BarScene s = bar();
  MeshLabelTransfer transfer;
  transfer.setJoinFlatBoundaries(false); // the cut alone (the halves meet on flat faces)
  std::vector<int> labels{3};
  EXPECT_FALSE(transfer.transfer(labels)); // nothing set
  EXPECT_TRUE(labels.empty());
  transfer.setInputMesh(s.mesh);
  EXPECT_FALSE(transfer.transfer(labels)); // no graph
  transfer.setInputGraph(s.graph);
  EXPECT_FALSE(transfer.transfer(labels)); // no parts
  transfer.setParts({{0, 1}, {2, 99}});
  EXPECT_FALSE(transfer.transfer(labels)); // node out of range
  transfer.setParts({{0, 1, 2, 3, 4, 5}});
  ASSERT_TRUE(transfer.transfer(labels));
  EXPECT_EQ(labels, std::vector<int>(s.mesh->numFaces(), 0));
  transfer.setInputMesh(std::make_shared<TriangleMesh>());
  EXPECT_FALSE(transfer.transfer(labels));
  transfer.setSmoothnessWeight(-1.0);
  EXPECT_DOUBLE_EQ(transfer.getSmoothnessWeight(), 0.3);
  pcl::console::setVerbosityLevel(pcl::console::L_INFO);
}

TEST(MeshLabelTransfer, OpenNonManifoldAndDegenerateMeshes)
{
  // The bar without its +x cap (open), plus a fin sharing an edge with two bar faces
  // (non-manifold), a zero-area face and a face with a NaN corner: labels stay finite and split
  // by side.
  BarScene s = bar();
  auto mesh = std::make_shared<TriangleMesh>(*s.mesh);
  std::vector<Eigen::Vector3i> kept;
  for (std::size_t f = 0; f < mesh->numFaces(); ++f)
    if (mesh->faceCentroid(static_cast<int>(f)).x() < 1.99)
      kept.push_back(mesh->faces[f]);
  mesh->faces = kept;
  const int a = mesh->faces[0][0], b = mesh->faces[0][1];
  mesh->vertices.push_back(mesh->vertices[a] + Eigen::Vector3d(0, 0, 0.3));
  mesh->faces.emplace_back(a, b, static_cast<int>(mesh->vertices.size()) - 1);
  mesh->faces.emplace_back(a, a, b);
  mesh->vertices.push_back(Eigen::Vector3d::Constant(std::nan("")));
  mesh->faces.emplace_back(a, b, static_cast<int>(mesh->vertices.size()) - 1); // NaN corner
  MeshLabelTransfer transfer;
  transfer.setJoinFlatBoundaries(false); // the cut alone (the halves meet on flat faces)
  transfer.setInputMesh(mesh);
  transfer.setInputGraph(s.graph);
  transfer.setParts(s.parts);
  std::vector<int> labels;
  ASSERT_TRUE(transfer.transfer(labels));
  ASSERT_EQ(labels.size(), mesh->numFaces());
  EXPECT_TRUE(std::isfinite(transfer.getEnergy()));
  for (std::size_t f = 0; f + 3 < mesh->numFaces(); ++f)
    EXPECT_EQ(labels[f], mesh->faceCentroid(static_cast<int>(f)).x() > 0.0 ? 1 : 0) << f;
}

TEST(CloudLabelTransfer, BarSamplesSplitAtTheMiddle)
{
  // The bar's vertices on a finer grid as a cloud, with and without outward normals.
  BarScene s = bar();
  const TriangleMesh fine = boxMesh({-2, -0.5, -0.5}, {2, 0.5, 0.5}, Eigen::Vector3i(40, 10, 10));
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>>();
  std::vector<int> expected;
  for (const Eigen::Vector3d& v : fine.vertices) {
    if (std::abs(v.x()) < 1e-9)
      continue; // keep the answer unambiguous
    cloud->push_back(pcl::PointXYZ(v.x(), v.y(), v.z()));
    // Outward normal of the box side the point is on (corners: any of them is fine).
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    if (std::abs(std::abs(v.x()) - 2) < 1e-9)
      n.x() = v.x() > 0 ? 1 : -1;
    else if (std::abs(std::abs(v.y()) - 0.5) < 1e-9)
      n.y() = v.y() > 0 ? 1 : -1;
    else
      n.z() = v.z() > 0 ? 1 : -1;
    normals->push_back(pcl::Normal(n.x(), n.y(), n.z()));
    expected.push_back(v.x() > 0 ? 1 : 0);
  }
  // A NaN point is left out with label -1.
  cloud->push_back(pcl::PointXYZ(std::nanf(""), 0, 0));
  normals->push_back(pcl::Normal(0, 0, 1));
  expected.push_back(-1);

  CloudLabelTransfer transfer;
  transfer.setJoinFlatBoundaries(false); // the cut alone (the halves meet on flat faces)
  transfer.setInputCloud(cloud);
  transfer.setInputGraph(s.graph);
  transfer.setParts(s.parts);
  std::vector<int> labels;
  ASSERT_TRUE(transfer.transfer(labels));
  EXPECT_EQ(labels, expected);
  transfer.setInputNormals(normals);
  ASSERT_TRUE(transfer.transfer(labels));
  EXPECT_EQ(labels, expected);
  // The thread count reaches the data term and the neighbour search, not the answer.
  EXPECT_EQ(transfer.getNumberOfThreads(), 0u);
  for (unsigned threads : {1u, 2u}) {
    CloudLabelTransfer threaded;
    threaded.setJoinFlatBoundaries(false);
    threaded.setNumberOfThreads(threads);
    EXPECT_EQ(threaded.getNumberOfThreads(), threads);
    threaded.setInputCloud(cloud);
    threaded.setInputNormals(normals);
    threaded.setInputGraph(s.graph);
    threaded.setParts(s.parts);
    std::vector<int> threaded_labels;
    ASSERT_TRUE(threaded.transfer(threaded_labels));
    EXPECT_EQ(threaded_labels, expected) << threads << " threads";
  }
  // By default the halves are joined when the points carry normals (their boundary crosses
  // the bar's flat sides); without normals nothing tells a flat boundary, and they stay apart.
  CloudLabelTransfer joining;
  joining.setInputCloud(cloud);
  joining.setInputGraph(s.graph);
  joining.setParts(s.parts);
  ASSERT_TRUE(joining.transfer(labels));
  EXPECT_EQ(labels, expected);
  joining.setInputNormals(normals);
  ASSERT_TRUE(joining.transfer(labels));
  std::vector<int> one(expected.size(), 0);
  one.back() = -1; // the NaN point
  EXPECT_EQ(labels, one);

  // Cut on ~300 voxel representatives instead of all 2078 points: away from the middle (more
  // than a voxel or two) every point keeps its side; each point takes its voxel's label.
  transfer.setMaxGraphPoints(300);
  std::vector<int> coarse;
  ASSERT_TRUE(transfer.transfer(coarse));
  ASSERT_EQ(coarse.size(), expected.size());
  for (std::size_t i = 0; i < coarse.size(); ++i)
    if (expected[i] < 0 || std::abs((*cloud)[i].x) > 0.6)
      EXPECT_EQ(coarse[i], expected[i]) << i;
  std::vector<int> again;
  ASSERT_TRUE(transfer.transfer(again));
  EXPECT_EQ(again, coarse);
  transfer.setMaxGraphPoints(0); // no limit

  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  normals->resize(3);
  transfer.setInputNormals(normals);
  EXPECT_FALSE(transfer.transfer(labels));
  EXPECT_TRUE(labels.empty());
  auto nan_only = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  nan_only->push_back(pcl::PointXYZ(std::nanf(""), 0, 0));
  transfer.setInputNormals(nullptr);
  transfer.setInputCloud(nan_only);
  EXPECT_FALSE(transfer.transfer(labels));
  transfer.setNeighbourCount(0);
  EXPECT_EQ(transfer.getNeighbourCount(), 10);
  pcl::console::setVerbosityLevel(pcl::console::L_INFO);
}
