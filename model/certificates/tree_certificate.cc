#include "model/certificates/tree_certificate.h"

#include <algorithm>
#include <cmath>

#include "model/certificates/bernstein_mesh_certificate.h"
#include "model/certificates/convexity_certificate.h"
#include "model/certificates/symmetric_eigen3.h"
#include "model/splines/bspline_volume_certificate.h"

namespace implicitfit {
namespace {

NodeCertificate Leaf(TreeConvexity c, std::string rule) {
  NodeCertificate r;
  r.convexity = c;
  r.rule = std::move(rule);
  return r;
}

NodeCertificate CertifyLeaf(const Model& model, int index) {
  const ModelNode& node = model.nodes()[index];
  const double* p = model.parameters().data() + node.first_parameter;
  switch (node.type) {
    case NodeType::kPlane:
      return Leaf(TreeConvexity::kConvexFunction, "plane: affine");
    case NodeType::kSphere:
      return Leaf(TreeConvexity::kConvexFunction, "sphere: |x - c| - r is convex");
    case NodeType::kCylinder:
      return Leaf(TreeConvexity::kConvexFunction, "cylinder: distance to a line minus r is convex");
    case NodeType::kCone:
      return Leaf(TreeConvexity::kConvexFunction,
                  "cone: exact signed distance to a convex single nappe");
    case NodeType::kTorus:
      return Leaf(TreeConvexity::kNotCertified, "torus: not convex");
    case NodeType::kEllipsoid:
      return Leaf(TreeConvexity::kConvexSolid,
                  "ellipsoid: convex solid, first-order distance not certified convex");
    case NodeType::kQuadric: {
      const double a[6] = {p[0], p[1], p[2], p[3], p[4], p[5]};
      const double frobenius = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] +
                                         2.0 * (a[3] * a[3] + a[4] * a[4] + a[5] * a[5]));
      if (SymmetricMinEigenvalue3(a) >= -kConvexityTolerance * frobenius)
        return Leaf(TreeConvexity::kConvexSolid,
                    "quadric with A positive semidefinite: convex solid, q / |grad q| not "
                    "certified convex");
      return Leaf(TreeConvexity::kNotCertified, "quadric with A indefinite");
    }
    case NodeType::kBernsteinPatch: {
      if (node.degree == 1)
        return Leaf(TreeConvexity::kConvexFunction, "bernstein_patch of degree 1: affine");
      if (!CertifyConvexity(node.degree, p).convex)
        return Leaf(TreeConvexity::kNotCertified,
                    "bernstein_patch: A^mu not all positive definite");
      NodeCertificate r = Leaf(TreeConvexity::kConvexFunction,
                               "bernstein_patch certified by A^mu: convex on its tetrahedron");
      r.domain_nodes.push_back(index);
      return r;
    }
    case NodeType::kBox:
      return Leaf(TreeConvexity::kConvexFunction, "box: exact signed distance to a convex set");
    case NodeType::kParaboloid:
      if (p[6] >= 0.0)
        return Leaf(TreeConvexity::kConvexFunction,
                    "paraboloid with curvature >= 0: h + (k/2)|w|^2 is convex");
      return Leaf(TreeConvexity::kNotCertified, "paraboloid with curvature < 0: concave");
    case NodeType::kSkeletonOffset: {
      if (SkeletonFeatureCount(node) > 0)
        return Leaf(TreeConvexity::kNotCertified,
                    "skeleton_offset with Coleman features: not certified");
      // One point, one segment (or a two-vertex polyline), one triangle: distance to a convex
      // set minus r.
      const SkeletonKind kind = static_cast<SkeletonKind>(node.variant);
      const bool one_element =
          node.count == 1 ||
          (node.count == 2 && kind != SkeletonKind::kPoints && kind != SkeletonKind::kTriangles) ||
          (node.count == 3 && kind == SkeletonKind::kTriangles);
      if (one_element)
        return Leaf(
            TreeConvexity::kConvexFunction,
            "skeleton_offset of one point, segment or triangle: distance to a convex set minus r");
      return Leaf(TreeConvexity::kNotCertified,
                  "skeleton_offset of several elements: a union of offsets, not certified");
    }
    case NodeType::kBlobs:
      return Leaf(TreeConvexity::kNotCertified, "blobs: not certified");
    case NodeType::kComplement:
      return Leaf(TreeConvexity::kNotCertified, "complement: not certified");
    case NodeType::kPartition:
      return Leaf(TreeConvexity::kNotCertified,
                  "partition: not certified (sum b_i f_i is not convex even for convex f_i)");
    case NodeType::kColemanFeatures:
      return Leaf(TreeConvexity::kNotCertified, "coleman_features: not certified");
    case NodeType::kPartitionSequence:
      return Leaf(TreeConvexity::kNotCertified,
                  "partition_sequence: not certified (sum w_j f_j is not convex even for convex "
                  "f_j)");
    case NodeType::kBernsteinMesh: {
      const MeshConvexityCertificate mesh = CertifyMeshConvexity(node.degree, node.grid, p);
      if (!mesh.convex_on_box)
        return Leaf(TreeConvexity::kNotCertified,
                    mesh.certified_tetrahedra < mesh.tetrahedra
                        ? "bernstein_mesh: some tetrahedra not certified (A^mu)"
                        : "bernstein_mesh: not C1 across its faces (a kink can be concave)");
      NodeCertificate r = Leaf(TreeConvexity::kConvexFunction,
                               "bernstein_mesh certified convex on its box (every A^mu positive "
                               "definite, C1 across the faces)");
      r.domain_nodes.push_back(index);
      return r;
    }
    case NodeType::kBSplineSurface:
      return Leaf(TreeConvexity::kNotCertified,
                  "bspline_surface: signed distance to an open patch, not certified");
    case NodeType::kBSplineVolume: {
      const VolumeConvexityCertificate c = CertifyVolumeConvexity(node.spline, p);
      if (!c.convex)
        return Leaf(TreeConvexity::kNotCertified,
                    "bspline_volume: not every Hessian Bernstein coefficient matrix is positive "
                    "definite");
      NodeCertificate r =
          Leaf(TreeConvexity::kConvexFunction,
               "bspline_volume certified (Hessian Bernstein coefficients positive definite on "
               "every cell): convex on its box");
      r.domain_nodes.push_back(index);
      return r;
    }
    case NodeType::kMorph:
    case NodeType::kUnion:
    case NodeType::kIntersection:
    case NodeType::kDifference:
      break;
  }
  return Leaf(TreeConvexity::kNotCertified,
              std::string(NodeTypeName(node.type)) + ": no convexity rule for this node type");
}

NodeCertificate CertifyOperator(const ModelNode& node, const std::vector<NodeCertificate>& all) {
  if (node.type == NodeType::kUnion)
    return Leaf(TreeConvexity::kNotCertified,
                "union: not certified (a union of convex solids "
                "is not convex in general)");
  if (node.type == NodeType::kDifference)
    return Leaf(TreeConvexity::kNotCertified, "difference: not certified");
  // Intersection.
  const bool sharp = node.order == 0;
  const bool convex_smoothing = node.smoothing == BlendSmoothing::kConvex;
  if (!sharp && !convex_smoothing)
    return Leaf(TreeConvexity::kNotCertified,
                "intersection with Li-Phillips smoothing: not certified (S_max is neither "
                "convex nor monotone)");
  TreeConvexity weakest = TreeConvexity::kConvexFunction;
  NodeCertificate r;
  for (int c : node.children) {
    const NodeCertificate& child = all[c];
    weakest = std::max(weakest, child.convexity);
    for (int d : child.domain_nodes)
      if (std::find(r.domain_nodes.begin(), r.domain_nodes.end(), d) == r.domain_nodes.end())
        r.domain_nodes.push_back(d);
  }
  r.convexity = weakest;
  if (weakest == TreeConvexity::kNotCertified) {
    r.domain_nodes.clear();
    r.rule = "intersection of children not all certified";
  } else if (sharp) {
    r.rule = weakest == TreeConvexity::kConvexFunction
                 ? "sharp intersection (max) of convex functions"
                 : "sharp intersection of convex solids";
  } else if (weakest == TreeConvexity::kConvexFunction) {
    r.rule = "convex-smoothing intersection of convex functions";
  } else {
    r.convexity = TreeConvexity::kNotCertified;
    r.domain_nodes.clear();
    r.rule =
        "convex-smoothing intersection needs convex functions, some child is only a "
        "convex solid";
  }
  return r;
}

// morph t f_A + (1 - t) f_B, t in [0, 1]: a convex combination of convex functions is convex.
NodeCertificate CertifyMorph(const ModelNode& node, const std::vector<NodeCertificate>& all) {
  NodeCertificate r = Leaf(TreeConvexity::kConvexFunction,
                           "morph of convex functions: a convex combination is convex");
  for (int c : node.children) {
    if (all[c].convexity != TreeConvexity::kConvexFunction)
      return Leaf(TreeConvexity::kNotCertified, "morph: needs convex functions as children");
    for (int d : all[c].domain_nodes)
      if (std::find(r.domain_nodes.begin(), r.domain_nodes.end(), d) == r.domain_nodes.end())
        r.domain_nodes.push_back(d);
  }
  return r;
}

void CertifyNode(const Model& model, int index, std::vector<NodeCertificate>* all) {
  const ModelNode& node = model.nodes()[index];
  for (int c : node.children) CertifyNode(model, c, all);
  if (node.type == NodeType::kMorph) {
    (*all)[index] = CertifyMorph(node, *all);
    return;
  }
  (*all)[index] = IsOperator(node.type) ? CertifyOperator(node, *all) : CertifyLeaf(model, index);
}

}  // namespace

const char* TreeConvexityName(TreeConvexity c) {
  switch (c) {
    case TreeConvexity::kConvexFunction:
      return "convex-function";
    case TreeConvexity::kConvexSolid:
      return "convex-solid";
    case TreeConvexity::kNotCertified:
      return "not-certified";
  }
  return "not-certified";
}

std::vector<NodeCertificate> CertifyTree(const Model& model) {
  std::vector<NodeCertificate> all(model.nodes().size());
  if (model.root() >= 0) CertifyNode(model, model.root(), &all);
  return all;
}

}  // namespace implicitfit
