// Jet fitting with Eigen (Cazals & Pouget 2005; the same steps as CGAL's
// Monge_via_jet_fitting, which tests/curvature/curvature_jet_test.cpp checks it against):
//  1. the fitting frame: the principal axes of the points' covariance (about their
//     centroid), the smallest one as the height axis, made right-handed; origin at the
//     first point (the vertex);
//  2. the height field z = sum_{k <= d} sum_{i <= k} A_{k,i} x^(k-i) y^i / ((k-i)! i!),
//     fitted by least squares with x, y scaled by the mean |x|, |y| (CGAL's
//     preconditioning), solved at degree 2 through the normal equations (Eigen's LDLT: 6
//     unknowns) where CGAL takes an SVD: the same minimizer; near singular, and at higher
//     degrees, by the SVD as CGAL;
//  3. the Monge form at (0, 0, A_0): normal (-A_x, -A_y, 1) normalized, Weingarten map
//     W = I^-1 II / |n| from the first and second fundamental forms of (x, y, z(x, y)),
//     written in an orthonormal basis of the tangent plane; its eigenvalues are the
//     principal curvatures along that normal, its eigenvectors the directions.
#include <Eigen/Dense>

#include <cmath>
#include <tuple>
#include <utility>

#include "common/curvature/curvature_internal.hpp"

namespace plumbago::curvature {

namespace {

struct FittingFrame {
  Eigen::Matrix3d axes;  // rows: x, y, z (the height axis) in world coordinates
};

FittingFrame principal_frame(const std::vector<glm::dvec3>& points) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const glm::dvec3& p : points) mean += Eigen::Vector3d(p.x, p.y, p.z);
  mean /= double(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const glm::dvec3& p : points) {
    Eigen::Vector3d d = Eigen::Vector3d(p.x, p.y, p.z) - mean;
    covariance += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);  // ascending eigenvalues
  Eigen::Vector3d x = eig.eigenvectors().col(2), y = eig.eigenvectors().col(1), z = eig.eigenvectors().col(0);
  if (x.cross(y).dot(z) < 0) z = -z;
  FittingFrame f;
  f.axes.row(0) = x, f.axes.row(1) = y, f.axes.row(2) = z;
  return f;
}

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// Row of the least-squares system for a point: the jet's monomials, preconditioned.
Eigen::VectorXd monomials(const Eigen::Vector3d& q, int degree, double scale) {
  Eigen::VectorXd row((degree + 1) * (degree + 2) / 2);
  for (int k = 0; k <= degree; ++k)
    for (int i = 0; i <= k; ++i)
      row(k * (k + 1) / 2 + i) =
          std::pow(q.x(), k - i) * std::pow(q.y(), i) / (factorial(i) * factorial(k - i) * std::pow(scale, k));
  return row;
}

// The preconditioned least squares: degree 2 by the normal equations (6 unknowns, fast);
// where they are near singular, and at higher degrees (whose monomials are often nearly
// dependent on a mesh's rings), by the SVD's minimum-norm solution, as CGAL.
Eigen::VectorXd least_squares(const std::vector<Eigen::Vector3d>& local, int degree, double scale) {
  const int unknowns = (degree + 1) * (degree + 2) / 2;
  if (degree == 2) {  // fixed size: the monomials of monomials() written out
    using Vector6 = Eigen::Matrix<double, 6, 1>;
    Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
    Vector6 right = Vector6::Zero();
    for (const Eigen::Vector3d& q : local) {
      double x = q.x() / scale, y = q.y() / scale;
      Vector6 row;
      row << 1, x, y, 0.5 * x * x, x * y, 0.5 * y * y;
      normal.selfadjointView<Eigen::Lower>().rankUpdate(row);
      right += row * q.z();
    }
    Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(normal);  // reads the lower triangle
    if (ldlt.info() == Eigen::Success && ldlt.isPositive() && ldlt.rcond() > 1e-10) return ldlt.solve(right);
  }
  Eigen::MatrixXd m(local.size(), unknowns);
  Eigen::VectorXd z(local.size());
  for (size_t r = 0; r < local.size(); ++r)
    m.row(Eigen::Index(r)) = monomials(local[r], degree, scale), z(Eigen::Index(r)) = local[r].z();
  return Eigen::JacobiSVD<Eigen::MatrixXd>(m, Eigen::ComputeThinU | Eigen::ComputeThinV).solve(z);
}

// The jet's coefficients A (bi-index (k, i) at k (k + 1) / 2 + i), in the frame.
bool fit_coefficients(const std::vector<Eigen::Vector3d>& local, int degree, Eigen::VectorXd& a) {
  double scale = 0;
  for (const Eigen::Vector3d& q : local) scale += std::abs(q.x()) + std::abs(q.y());
  scale /= 2.0 * double(local.size());
  if (!(scale > 0)) return false;
  a = least_squares(local, degree, scale);
  for (int k = 0; k <= degree; ++k)
    for (int i = 0; i <= k; ++i) a(k * (k + 1) / 2 + i) /= std::pow(scale, k);
  return a.allFinite();
}

glm::dvec3 to_world(const FittingFrame& f, const Eigen::Vector3d& v) {
  Eigen::Vector3d w = f.axes.transpose() * v;
  return {w.x(), w.y(), w.z()};
}

// Step 3: the Monge form at the origin from the jet's first and second derivatives.
JetFit monge_form(const FittingFrame& f, const Eigen::VectorXd& a) {
  const double ax = a(1), ay = a(2), axx = a(3), axy = a(4), ayy = a(5);
  Eigen::Vector3d xu(1, 0, ax), xv(0, 1, ay), n(-ax, -ay, 1);
  const double norm2 = n.squaredNorm();
  n /= std::sqrt(norm2);
  const double e = xu.squaredNorm(), g = xv.squaredNorm(), fuv = xu.dot(xv), s = std::sqrt(norm2) * norm2;
  Eigen::Matrix2d w;  // I^-1 II / |n| in the basis (xu, xv)
  w << (g * axx - fuv * axy) / s, (g * axy - fuv * ayy) / s, (e * axy - fuv * axx) / s, (e * ayy - fuv * axy) / s;
  Eigen::Vector3d t1 = xu.normalized(), t2 = (xv - xu.dot(xv) / e * xu).normalized();  // orthonormal tangent basis
  Eigen::Matrix<double, 3, 2> basis;
  basis << xu, xv;
  Eigen::Matrix<double, 3, 2> ortho;
  ortho << t1, t2;
  Eigen::Matrix2d to_ortho = ortho.transpose() * basis;  // (xu, xv) coordinates -> (t1, t2) coordinates
  Eigen::Matrix2d sym = to_ortho * w * to_ortho.inverse();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(0.5 * (sym + sym.transpose()));  // ascending
  Eigen::Vector3d d_small = ortho * eig.eigenvectors().col(0), d_large = ortho * eig.eigenvectors().col(1);
  // Along n a sphere bulging towards n has eigenvalues -1/R; ours are +1/R with the normal
  // outward: k = -eigenvalue, so the larger eigenvalue is our k_min.
  return {to_world(f, n), to_world(f, d_large.normalized()), to_world(f, d_small.normalized()), -eig.eigenvalues()(1),
          -eig.eigenvalues()(0)};
}

}  // namespace

bool jet_fit_finite(const JetFit& f) {
  auto finite = [](const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  return finite(f.normal) && finite(f.d_min) && finite(f.d_max) && std::isfinite(f.k_min) && std::isfinite(f.k_max);
}

bool eigen_fit_vertex(const std::vector<glm::dvec3>& points, int degree, const glm::vec3& mesh_normal, JetFit& out) {
  FittingFrame frame = principal_frame(points);
  std::vector<Eigen::Vector3d> local;
  for (const glm::dvec3& p : points)
    local.push_back(frame.axes * Eigen::Vector3d(p.x - points[0].x, p.y - points[0].y, p.z - points[0].z));
  Eigen::VectorXd a;
  if (!fit_coefficients(local, degree, a)) return false;
  out = monge_form(frame, a);
  if (glm::dot(out.normal, glm::dvec3(mesh_normal)) < 0) {  // the mesh's side: curvatures change sign and order
    out.normal = -out.normal;
    std::swap(out.d_min, out.d_max);
    std::tie(out.k_min, out.k_max) = std::pair(-out.k_max, -out.k_min);
  }
  return jet_fit_finite(out);
}

}  // namespace plumbago::curvature
