// orthocheck's bundle-adjustment problems solved by Ceres, for the comparison of
// docs/limits.md ("Bundle adjustment's cost"). A development benchmark only: nothing in the
// Rust crates depends on it. Built by build.sh, run by run.sh.
//
// The problem file is written by `cargo run --release -p orthocheck-benches --example
// ceres_export` (benches/ceres_export.rs): observations, the start and orthocheck's own
// result, all in the units orthocheck's adjustment works in (sfm::Units: image coordinates
// mapped by y -> (y - centre) / scale, scale a power of two). Costs are printed in the
// input's units, ½ Σ ‖r‖² times scale², the units of docs/limits.md's table.
//
// The model is orthocheck's: image = the first two rows of R X + t. Parameter blocks: per
// frame a rotation and a translation (2), per point its position (3). Frame 1's rotation is
// held by SetParameterBlockConstant (the rotation gauge); the 3-D shift gauge (X + c,
// t - rows(R) c) is left to Levenberg–Marquardt's damping, as orthocheck leaves the part
// of it its re-centring does not remove. The rotation is either
//   quat:   a unit quaternion (Ceres' order w, x, y, z) on ceres::QuaternionManifold (the
//           update exp(δ) ⊗ q, Ceres' usual choice), or
//   matrix: the 3 × 3 matrix (9 numbers, row by row) on a manifold whose update is
//           R exp([δ]×), orthocheck's own parametrisation.
// Residuals by AutoDiffCostFunction<…, 2, 4 or 9, 2, 3>. The points are eliminated by the
// Schur complement (points in elimination group 0, cameras in group 1).
//
// Usage: bench PROBLEM.txt [--solver sparse,dense] [--threads 1,2] [--rot quat,matrix]
//        [--tol tight,default] [--repeat 5] [--sparse-lib suite_sparse|eigen_sparse|cx_sparse]
//        [--dense-lib eigen|lapack] [--max-iterations 200] [--target COST] [--verbose 1]
//        (build.sh puts it in target/ceres_bench/bench)
// Each configuration is run --repeat times from the start (the Problem built afresh each
// time); printed: the median wall time of building the Problem and solving, the median of
// Solve alone, the iterations (successful + unsuccessful), the final cost, and the median
// time until the cost first reached the target (input units; by default orthocheck's final
// cost from the file, times 1 + 1e-10: "an equal cost" to ten digits), read from Ceres'
// per-iteration summaries (cumulative_time_in_seconds, plus the time to build the Problem).
//
// Tolerances: "tight" stops as orthocheck does, at the rounding of the cost and of the
// parameters: function_tolerance = parameter_tolerance = 4ε (orthocheck stops when a step
// lowers the cost by at most 4ε·cost or is shorter than 4ε·‖x‖), gradient_tolerance = 0
// (orthocheck has no gradient test); "default" is Ceres' defaults (1e-6, 1e-8, 1e-10).
// max_num_iterations = 200 in both (orthocheck: 200 accepted steps at most, `sfm::bundle::MAX_ITERATIONS`).

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <ceres/ceres.h>
#include <ceres/manifold.h>
#include <ceres/rotation.h>

namespace {

struct Obs {
  int f, j;
  double x, y;
};

using Rot = std::array<double, 9>;  // row-major
using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;

struct Problem {
  std::string name;
  double centre[2] = {0, 0}, scale = 1;
  int frames = 0, points = 0, nobs = 0;
  int rust_iterations = 0;
  double rust_cost = 0, rust_start_cost = 0, rust_secs = 0, rust_overhead = 0;
  std::vector<Rot> rot, rust_rot;
  std::vector<Vec2> trans, rust_trans;
  std::vector<Vec3> pts, rust_pts;
  std::vector<Obs> obs;
};

Problem read_problem(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    std::cerr << "cannot read " << path << "\n";
    std::exit(2);
  }
  Problem p;
  std::string line, tag;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    s >> tag;
    if (tag == "name") {
      s >> p.name;
    } else if (tag == "units") {
      s >> p.centre[0] >> p.centre[1] >> p.scale;
    } else if (tag == "sizes") {
      s >> p.frames >> p.points >> p.nobs;
      p.rot.resize(p.frames);
      p.trans.resize(p.frames);
      p.rust_rot.resize(p.frames);
      p.rust_trans.resize(p.frames);
      p.pts.resize(p.points);
      p.rust_pts.resize(p.points);
      p.obs.reserve(p.nobs);
    } else if (tag == "rust") {
      s >> p.rust_iterations >> p.rust_cost >> p.rust_start_cost >> p.rust_secs >>
          p.rust_overhead;
    } else if (tag == "frame" || tag == "rust_frame") {
      int f;
      s >> f;
      Rot& r = tag == "frame" ? p.rot[f] : p.rust_rot[f];
      Vec2& t = tag == "frame" ? p.trans[f] : p.rust_trans[f];
      for (double& v : r) s >> v;
      s >> t[0] >> t[1];
    } else if (tag == "point" || tag == "rust_point") {
      int j;
      s >> j;
      Vec3& x = tag == "point" ? p.pts[j] : p.rust_pts[j];
      s >> x[0] >> x[1] >> x[2];
    } else if (tag == "obs") {
      Obs o;
      s >> o.f >> o.j >> o.x >> o.y;
      p.obs.push_back(o);
    }
    if (s.fail()) {
      std::cerr << path << ": cannot read the line: " << line << "\n";
      std::exit(2);
    }
  }
  if ((int)p.obs.size() != p.nobs) {
    std::cerr << path << ": " << p.obs.size() << " observations, the header says " << p.nobs
              << "\n";
    std::exit(2);
  }
  return p;
}

// ½ Σ ‖rows(R) X + t − y‖² in the file's units; one function for every solver's answer.
double cost(const Problem& p, const std::vector<Rot>& rot, const std::vector<Vec2>& trans,
            const std::vector<Vec3>& pts) {
  double c = 0;
  for (const Obs& o : p.obs) {
    const Rot& r = rot[o.f];
    const Vec3& x = pts[o.j];
    const double e0 = r[0] * x[0] + r[1] * x[1] + r[2] * x[2] + trans[o.f][0] - o.x;
    const double e1 = r[3] * x[0] + r[4] * x[1] + r[5] * x[2] + trans[o.f][1] - o.y;
    c += e0 * e0 + e1 * e1;
  }
  return c / 2;
}

// The orthographic residual with the rotation a unit quaternion (w, x, y, z).
struct OrthoQuat {
  double x, y;
  template <typename T>
  bool operator()(const T* q, const T* t, const T* X, T* r) const {
    const T w = q[0], a = q[1], b = q[2], c = q[3];
    const T r00 = T(1) - T(2) * (b * b + c * c), r01 = T(2) * (a * b - w * c),
            r02 = T(2) * (a * c + w * b);
    const T r10 = T(2) * (a * b + w * c), r11 = T(1) - T(2) * (a * a + c * c),
            r12 = T(2) * (b * c - w * a);
    r[0] = r00 * X[0] + r01 * X[1] + r02 * X[2] + t[0] - x;
    r[1] = r10 * X[0] + r11 * X[1] + r12 * X[2] + t[1] - y;
    return true;
  }
};

// The orthographic residual with the rotation a 3 × 3 matrix, row by row.
struct OrthoMatrix {
  double x, y;
  template <typename T>
  bool operator()(const T* R, const T* t, const T* X, T* r) const {
    r[0] = R[0] * X[0] + R[1] * X[1] + R[2] * X[2] + t[0] - x;
    r[1] = R[3] * X[0] + R[4] * X[1] + R[5] * X[2] + t[1] - y;
    return true;
  }
};

// SO(3) as 3 × 3 matrices (row by row) with orthocheck's update R ⊞ δ = R exp([δ]×).
class RightSO3 final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return 9; }
  int TangentSize() const override { return 3; }

  bool Plus(const double* R, const double* d, double* out) const override {
    double E[9];
    ceres::AngleAxisToRotationMatrix(d, ceres::RowMajorAdapter3x3(E));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        out[3 * i + j] = R[3 * i] * E[j] + R[3 * i + 1] * E[3 + j] + R[3 * i + 2] * E[6 + j];
    return true;
  }

  // ∂(R exp([δ]×))/∂δ_k at δ = 0 is R [e_k]×: a 9 × 3 matrix, row-major.
  bool PlusJacobian(const double* R, double* J) const override {
    for (int k = 0; k < 3; ++k) {
      double K[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
      // [e_k]×
      if (k == 0) { K[5] = -1; K[7] = 1; }
      if (k == 1) { K[2] = 1; K[6] = -1; }
      if (k == 2) { K[1] = -1; K[3] = 1; }
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          J[(3 * i + j) * 3 + k] =
              R[3 * i] * K[j] + R[3 * i + 1] * K[3 + j] + R[3 * i + 2] * K[6 + j];
    }
    return true;
  }

  bool Minus(const double* Y, const double* X, double* d) const override {
    double M[9];  // Xᵀ Y
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        M[3 * a + b] = X[a] * Y[b] + X[3 + a] * Y[3 + b] + X[6 + a] * Y[6 + b];
    ceres::RotationMatrixToAngleAxis(ceres::RowMajorAdapter3x3(static_cast<const double*>(M)),
                                     d);
    return true;
  }

  // ∂ log(Xᵀ Y)/∂Y at Y = X: δ = vee of the skew part of Xᵀ dY. A 3 × 9 matrix, row-major.
  bool MinusJacobian(const double* X, double* J) const override {
    std::fill(J, J + 27, 0.0);
    // δ0 = (M21 − M12)/2, δ1 = (M02 − M20)/2, δ2 = (M10 − M01)/2, M_ab = Σ_i X_ia dY_ib
    const int pairs[3][2][2] = {{{2, 1}, {1, 2}}, {{0, 2}, {2, 0}}, {{1, 0}, {0, 1}}};
    for (int c = 0; c < 3; ++c)
      for (int s = 0; s < 2; ++s) {
        const int a = pairs[c][s][0], b = pairs[c][s][1];
        const double sign = s == 0 ? 0.5 : -0.5;
        for (int i = 0; i < 3; ++i) J[c * 9 + 3 * i + b] += sign * X[3 * i + a];
      }
    return true;
  }
};

std::array<double, 4> to_quaternion(const Rot& r) {
  Eigen::Matrix3d m;
  m << r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8];
  Eigen::Quaterniond q(m);
  q.normalize();
  return {q.w(), q.x(), q.y(), q.z()};
}

Rot from_quaternion(const std::array<double, 4>& q) {
  Rot r;
  ceres::QuaternionToRotation(q.data(), ceres::RowMajorAdapter3x3(r.data()));
  return r;
}

struct Config {
  ceres::LinearSolverType solver;
  int threads;
  bool quat;
  bool tight;
};

std::string config_name(const Config& c) {
  std::string s = c.solver == ceres::SPARSE_SCHUR ? "SPARSE_SCHUR" : "DENSE_SCHUR";
  s += ", " + std::to_string(c.threads) + (c.threads == 1 ? " thread" : " threads");
  s += c.quat ? ", quaternion" : ", matrix R·exp";
  s += c.tight ? ", tolerances 4ε" : ", default tolerances";
  return s;
}

struct Run {
  double total_s, solve_s, cost_input, ceres_final_input, ceres_initial_input;
  double reach_s;  // build + Solve time until the cost is at most the target; < 0: never
  int successful, unsuccessful;
  std::string termination;
};

Run solve_once(const Problem& p, const Config& c, ceres::SparseLinearAlgebraLibraryType sparse,
               ceres::DenseLinearAlgebraLibraryType dense, int max_iterations, double target,
               bool verbose) {
  using clock = std::chrono::steady_clock;
  std::vector<std::array<double, 4>> quat(p.frames);
  std::vector<Rot> rot = p.rot;
  std::vector<Vec2> trans = p.trans;
  std::vector<Vec3> pts = p.pts;
  if (c.quat)
    for (int f = 0; f < p.frames; ++f) quat[f] = to_quaternion(p.rot[f]);

  const auto t0 = clock::now();
  ceres::Problem problem;
  auto* ordering = new ceres::ParameterBlockOrdering;
  for (const Obs& o : p.obs) {
    ceres::CostFunction* cf;
    double* r;
    if (c.quat) {
      cf = new ceres::AutoDiffCostFunction<OrthoQuat, 2, 4, 2, 3>(new OrthoQuat{o.x, o.y});
      r = quat[o.f].data();
    } else {
      cf = new ceres::AutoDiffCostFunction<OrthoMatrix, 2, 9, 2, 3>(new OrthoMatrix{o.x, o.y});
      r = rot[o.f].data();
    }
    problem.AddResidualBlock(cf, nullptr, r, trans[o.f].data(), pts[o.j].data());
  }
  for (int f = 0; f < p.frames; ++f) {
    double* r = c.quat ? quat[f].data() : rot[f].data();
    if (!problem.HasParameterBlock(r)) continue;
    if (c.quat)
      problem.SetManifold(r, new ceres::QuaternionManifold);
    else
      problem.SetManifold(r, new RightSO3);
    if (f == 0) problem.SetParameterBlockConstant(r);
    ordering->AddElementToGroup(r, 1);
    ordering->AddElementToGroup(trans[f].data(), 1);
  }
  for (int j = 0; j < p.points; ++j) ordering->AddElementToGroup(pts[j].data(), 0);

  ceres::Solver::Options options;
  options.linear_solver_type = c.solver;
  options.sparse_linear_algebra_library_type = sparse;
  options.dense_linear_algebra_library_type = dense;
  options.linear_solver_ordering.reset(ordering);
  options.num_threads = c.threads;
  options.max_num_iterations = max_iterations;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  if (c.tight) {
    options.function_tolerance = 4 * std::numeric_limits<double>::epsilon();
    options.parameter_tolerance = 4 * std::numeric_limits<double>::epsilon();
    options.gradient_tolerance = 0;
  }
  std::string why;
  if (!options.IsValid(&why)) {
    std::cerr << "invalid options: " << why << "\n";
    std::exit(2);
  }
  ceres::Solver::Summary summary;
  const auto t1 = clock::now();
  ceres::Solve(options, &problem, &summary);
  const auto t2 = clock::now();

  if (c.quat)
    for (int f = 0; f < p.frames; ++f) rot[f] = from_quaternion(quat[f]);
  const double s2 = p.scale * p.scale;
  Run run;
  run.total_s = std::chrono::duration<double>(t2 - t0).count();
  run.solve_s = std::chrono::duration<double>(t2 - t1).count();
  run.cost_input = cost(p, rot, trans, pts) * s2;
  run.ceres_final_input = summary.final_cost * s2;
  run.ceres_initial_input = summary.initial_cost * s2;
  run.reach_s = -1;
  for (const ceres::IterationSummary& it : summary.iterations)
    if (it.cost * s2 <= target) {
      run.reach_s = std::chrono::duration<double>(t1 - t0).count() + it.cumulative_time_in_seconds;
      break;
    }
  run.successful = summary.num_successful_steps;
  run.unsuccessful = summary.num_unsuccessful_steps;
  run.termination = ceres::TerminationTypeToString(summary.termination_type);
  for (const char* why : {"Function tolerance", "Parameter tolerance", "Gradient tolerance",
                          "Maximum number of iterations", "Minimum trust region radius"})
    if (summary.message.find(why) != std::string::npos) run.termination += std::string(": ") + why;
  if (verbose) {
    std::printf("#   iteration, cost (input units), successful, step solver s, iteration s, "
                "cumulative s\n");
    for (const ceres::IterationSummary& it : summary.iterations)
      std::printf("#   %d %.12e %d %.4f %.4f %.4f\n", it.iteration, it.cost * s2,
                  it.step_is_successful ? 1 : 0, it.step_solver_time_in_seconds,
                  it.iteration_time_in_seconds, it.cumulative_time_in_seconds);
    std::printf("%s\n", summary.FullReport().c_str());
  }
  if (summary.termination_type == ceres::FAILURE) {
    std::cerr << summary.FullReport() << "\n";
  }
  return run;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  if (argc < 2) {
    std::cerr << "usage: bench PROBLEM.txt [--solver sparse,dense] [--threads 1,2] "
                 "[--rot quat,matrix] [--tol tight,default] [--repeat 5] "
                 "[--sparse-lib suite_sparse|eigen_sparse|cx_sparse] [--dense-lib eigen|lapack]\n";
    return 2;
  }
  std::string solvers = "sparse,dense", threads = "1,2", rots = "quat,matrix",
              tols = "tight", sparse_lib = "suite_sparse", dense_lib = "eigen";
  int repeat = 5, max_iterations = 200;
  double target = -1;
  bool verbose = false;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--solver") solvers = v;
    else if (a == "--threads") threads = v;
    else if (a == "--rot") rots = v;
    else if (a == "--tol") tols = v;
    else if (a == "--repeat") repeat = std::stoi(v);
    else if (a == "--max-iterations") max_iterations = std::stoi(v);
    else if (a == "--target") target = std::stod(v);
    else if (a == "--verbose") verbose = v == "1";
    else if (a == "--sparse-lib") sparse_lib = v;
    else if (a == "--dense-lib") dense_lib = v;
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  ceres::SparseLinearAlgebraLibraryType sparse;
  ceres::DenseLinearAlgebraLibraryType dense;
  std::string up = sparse_lib, upd = dense_lib;
  std::transform(up.begin(), up.end(), up.begin(), ::toupper);
  std::transform(upd.begin(), upd.end(), upd.begin(), ::toupper);
  if (!ceres::StringToSparseLinearAlgebraLibraryType(up, &sparse) ||
      !ceres::StringToDenseLinearAlgebraLibraryType(upd, &dense)) {
    std::cerr << "unknown linear algebra library\n";
    return 2;
  }

  const Problem p = read_problem(argv[1]);
  const double s2 = p.scale * p.scale;
  const double start = cost(p, p.rot, p.trans, p.pts) * s2;
  const double rust = cost(p, p.rust_rot, p.rust_trans, p.rust_pts) * s2;
  if (target < 0) target = rust * (1 + 1e-10);
  std::printf("# %s: %d frames, %d points, %d observations; scale %g; Ceres %s\n",
              p.name.c_str(), p.frames, p.points, p.nobs, p.scale, CERES_VERSION_STRING);
  std::printf("# start cost %.12e (orthocheck's figure %.12e)\n", start, p.rust_start_cost);
  std::printf(
      "# orthocheck bundle_adjust: %d iterations, cost %.12e (recomputed here: %.12e); "
      "median %.4f s (of which %.4f s outside the iterations)\n",
      p.rust_iterations, p.rust_cost, rust, p.rust_secs, p.rust_overhead);
  std::printf("# target cost %.12e; max_num_iterations %d; %d runs each\n", target,
              max_iterations, repeat);
  std::printf(
      "| problem | solver | median s (build + solve) | median s (Solve) | iterations "
      "(successful + unsuccessful) | final cost | termination | median s to the target "
      "|\n|---|---|---:|---:|---|---:|---|---:|\n");
  std::fflush(stdout);
  for (const std::string& tol : split(tols))
    for (const std::string& rot : split(rots))
      for (const std::string& sv : split(solvers))
        for (const std::string& th : split(threads)) {
          Config c{sv == "sparse" ? ceres::SPARSE_SCHUR : ceres::DENSE_SCHUR, std::stoi(th),
                   rot == "quat", tol == "tight"};
          std::vector<double> total, solve, reach;
          Run last;
          for (int r = 0; r < repeat; ++r) {
            last = solve_once(p, c, sparse, dense, max_iterations, target,
                              verbose && r + 1 == repeat);
            total.push_back(last.total_s);
            solve.push_back(last.solve_s);
            reach.push_back(last.reach_s < 0 ? INFINITY : last.reach_s);
          }
          const double r = median(reach);
          char reach_text[32];
          if (std::isinf(r)) std::snprintf(reach_text, sizeof reach_text, "never");
          else std::snprintf(reach_text, sizeof reach_text, "%.4f", r);
          std::printf("| %s | Ceres %s | %.4f | %.4f | %d (%d + %d) | %.12e | %s | %s |\n",
                      p.name.c_str(), config_name(c).c_str(), median(total), median(solve),
                      last.successful + last.unsuccessful, last.successful, last.unsuccessful,
                      last.cost_input, last.termination.c_str(), reach_text);
          if (std::fabs(last.cost_input - last.ceres_final_input) > 1e-9 * last.cost_input ||
              std::fabs(last.ceres_initial_input - start) > 1e-9 * start)
            std::printf("#   note: Ceres' own initial / final cost %.12e / %.12e\n",
                        last.ceres_initial_input, last.ceres_final_input);
          std::fflush(stdout);
        }
  return 0;
}
