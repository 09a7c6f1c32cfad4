// Eigenvalues of a real symmetric 3x3 matrix in closed form, without heap allocation.
//
// Maths (trigonometric solution, then deflation for accuracy). Shift and scale:
//   q = tr(A)/3,  p = sqrt(|A - qI|_F^2 / 6),  B = (A - qI)/p,  r = det(B)/2 in [-1, 1],
//   phi = acos(r)/3,  eigenvalues q + 2p cos(phi + 2 pi j/3), j = 0, 1, 2.
// The root with the largest gap is well conditioned in r (the largest one when r >= 0, the
// smallest when r < 0); the other two are ill conditioned near a double eigenvalue (errors
// ~ sqrt(machine eps) |A|) when taken from the same formula. So only that isolated eigenvalue is
// taken from it; its eigenvector v is the largest cross product of two rows of A - lambda I, and
// the remaining two eigenvalues are those of the 2x2 matrix A restricted to v's orthogonal
// complement, (m00 + m11)/2 -/+ hypot((m00 - m11)/2, m01). Every eigenvalue is then accurate
// to a small multiple of machine epsilon times |A| (checked against Eigen's iterative solver in
// tests/model/certificates/symmetric_eigen3_test.cc).
#pragma once

namespace implicitfit {

// a = {a00, a11, a22, a01, a02, a12}; out: the three eigenvalues in ascending order.
void SymmetricEigenvalues3(const double a[6], double out[3]);
// The smallest eigenvalue only (the same value as out[0] above, sometimes cheaper).
double SymmetricMinEigenvalue3(const double a[6]);

}  // namespace implicitfit
