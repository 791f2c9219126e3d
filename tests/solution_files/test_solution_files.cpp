// The solution-file format of `rodvv check`: bit-exact round trip, second-order derivation of what a
// file may leave out, and a clear InputError (file, JSON path or CSV line, what was expected) for
// every malformed file.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/solution_files/solution_file.hpp"

namespace rodvv::solution_files {
namespace {

PlanarRodSolution awkward_planar(std::size_t n) {
  PlanarRodSolution rod;
  rod.length = 1.7;
  for (std::size_t i = 0; i <= n; ++i) {
    const double s = 1.7 * double(i) / double(n);  // i/n in double: not a short decimal
    rod.s.push_back(s);
    rod.x.push_back(std::sin(s) / 3.0);
    rod.y.push_back(-std::expm1(s) * 1e-300);  // tiny but normal
    rod.theta.push_back(std::atan(s) - 2.0 / 3.0);
    rod.kappa.push_back(1.0 / (1.0 + s));
    rod.force_x.push_back(-1.0 / 7.0);
    rod.force_y.push_back(std::nextafter(0.3, 1.0));
    rod.axial_force.push_back(std::cos(s) / 11.0);
    rod.shear_force.push_back(std::sin(s) / 13.0);
    rod.bending_stiffness.push_back(2.3 + s * 1e-17);
    rod.natural_curvature.push_back(0.0);
    rod.potential.push_back(s * s / 9.0);
  }
  rod.axial_stiffness = 1.0 / 3e-5;
  rod.shear_stiffness = 7e4 / 3.0;
  rod.iterations = 12;
  rod.residual = 3.1e-15;
  return rod;
}

// Shortest round-trip decimal text of a double.
std::string shortest(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return {buffer, end};
}

SolutionFile file_of(Solution solution) {
  SolutionFile file;
  file.case_name = "elastica/mattiasson-2";
  file.parameters = {{"L", 1.7}, {"EI", 2.3}, {"alpha", 2.0 / 3.0}};
  file.resolution_name = "N";
  file.level = 40;
  file.solver = "a test \"solver\"\n";
  file.cpu_seconds = 12.0 / 7.0;
  file.solution = std::move(solution);
  return file;
}

TEST(SolutionFile, PlanarRoundTripIsBitExact) {
  const PlanarRodSolution rod = awkward_planar(40);
  const SolutionFile back = parse_solution(format_solution(file_of(rod)), "memory", ".");
  const auto& read = std::get<PlanarRodSolution>(back.solution);
  for (const auto& [written, got] :
       {std::pair{&rod.s, &read.s}, {&rod.x, &read.x}, {&rod.y, &read.y}, {&rod.theta, &read.theta},
        {&rod.kappa, &read.kappa}, {&rod.force_x, &read.force_x}, {&rod.force_y, &read.force_y},
        {&rod.axial_force, &read.axial_force}, {&rod.shear_force, &read.shear_force},
        {&rod.bending_stiffness, &read.bending_stiffness}, {&rod.potential, &read.potential}})
    EXPECT_EQ(*written, *got);  // operator== on doubles: the same bits (no NaN)
  EXPECT_EQ(read.axial_stiffness, rod.axial_stiffness);
  EXPECT_EQ(read.shear_stiffness, rod.shear_stiffness);
  EXPECT_EQ(read.length, rod.length);
  EXPECT_EQ(read.iterations, 12u);
  EXPECT_EQ(back.parameters, file_of(rod).parameters);
  EXPECT_EQ(back.solver, "a test \"solver\"\n");
  EXPECT_EQ(back.cpu_seconds, 12.0 / 7.0);
  EXPECT_EQ(back.wall_seconds, 0.0);
  EXPECT_EQ(back.level, 40.0);
  EXPECT_TRUE(back.derived.empty());
  EXPECT_TRUE(back.missing.empty());
}

TEST(SolutionFile, TrajectoryRoundTripIsBitExact) {
  Trajectory trajectory;
  for (int i = 0; i < 50; ++i) trajectory.record(0.1 * i / 3.0, std::sin(i / 7.0), -std::cos(i / 9.0) / 3.0);
  trajectory.steps = 49;
  trajectory.rhs_evaluations = 196;
  SolutionFile file = file_of(trajectory);
  file.resolution_name = "omega_dt";
  file.level = 0.1 / 3.0;
  const SolutionFile back = parse_solution(format_solution(file), "memory", ".");
  const auto& read = std::get<Trajectory>(back.solution);
  EXPECT_EQ(read.t, trajectory.t);
  EXPECT_EQ(read.theta, trajectory.theta);
  EXPECT_EQ(read.theta_dot, trajectory.theta_dot);
  EXPECT_EQ(read.rhs_evaluations, 196u);
  EXPECT_EQ(back.level, 0.1 / 3.0);
}

TEST(SolutionFile, SpatialRoundTripIsBitExact) {
  SpatialRodSolution rod;
  rod.length = 1.3;
  for (int i = 0; i < 9; ++i) {
    const double s = 1.3 * i / 8.0 + (i == 8 ? 0.0 : 1e-3 / 3.0);
    const Mat3 frame = Eigen::AngleAxisd(s / 3.0, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
    if (i < 8) {  // stations at element midpoints
      rod.s.push_back(s);
      rod.position.push_back(Vec3(s, std::sin(s) / 7.0, -s * s / 3.0));
      rod.frame.push_back(frame);
      rod.strain_u.push_back(Vec3(0.1 / 3.0, -s, s * s));
      rod.strain_v.push_back(Vec3(1.0 + 1e-6 / 3.0, 0.0, 0.0));
      rod.stiffness.push_back(Vec3(0.7, 1.0, 2.3) * 1.7);
      rod.natural_strain.push_back(Vec3(0.0, 0.3, 0.0));
      rod.force_n.push_back(Vec3(0.0, 0.0, -2.0 / 3.0));
      rod.moment_m.push_back(Vec3(s / 11.0, 0.1, -0.2));
      rod.potential.push_back(s / 9.0);
      rod.shear_energy.push_back(1e-12 / 7.0);
    }
    rod.vertex_s.push_back(1.3 * i / 8.0);
    rod.vertex_position.push_back(Vec3(s, 1.0 / 3.0, 0.0));
    rod.vertex_frame.push_back(frame);
  }
  rod.iterations = 5;
  SolutionFile file = file_of(rod);
  const SolutionFile back = parse_solution(format_solution(file), "memory", ".");
  const auto& read = std::get<SpatialRodSolution>(back.solution);
  EXPECT_EQ(read.s, rod.s);
  EXPECT_EQ(read.potential, rod.potential);
  EXPECT_EQ(read.shear_energy, rod.shear_energy);
  EXPECT_EQ(read.vertex_s, rod.vertex_s);
  for (std::size_t i = 0; i < rod.s.size(); ++i) {
    EXPECT_EQ(read.position[i], rod.position[i]);
    EXPECT_EQ(read.frame[i], rod.frame[i]);
    EXPECT_EQ(read.strain_u[i], rod.strain_u[i]);
    EXPECT_EQ(read.strain_v[i], rod.strain_v[i]);
    EXPECT_EQ(read.stiffness[i], rod.stiffness[i]);
    EXPECT_EQ(read.natural_strain[i], rod.natural_strain[i]);
    EXPECT_EQ(read.force_n[i], rod.force_n[i]);
    EXPECT_EQ(read.moment_m[i], rod.moment_m[i]);
  }
  for (std::size_t i = 0; i < rod.vertex_s.size(); ++i) {
    EXPECT_EQ(read.vertex_position[i], rod.vertex_position[i]);
    EXPECT_EQ(read.vertex_frame[i], rod.vertex_frame[i]);
  }
  EXPECT_EQ(read.iterations, 5u);
  EXPECT_TRUE(back.missing.empty());
  EXPECT_TRUE(back.derived.empty());
}

// A 3-D rod's trajectory in long form: snapshots with their own vertex counts (a remeshing solver), times and
// positions that are not short decimals, back bit for bit.
TEST(SolutionFile, RodTrajectoryRoundTripIsBitExact) {
  RodTrajectory trajectory;
  for (int k = 0; k < 4; ++k) {
    RodSnapshot snapshot;
    const int vertices = 3 + k;
    for (int i = 0; i < vertices; ++i) {
      const double s = 1.3 * i / (vertices - 1);
      snapshot.s.push_back(s);
      snapshot.position.push_back(Vec3(s, std::sin(s + k) / 7.0, -1e-300 * k / 3.0));
    }
    trajectory.t.push_back(0.1 * k / 3.0);
    trajectory.snapshots.push_back(std::move(snapshot));
  }
  trajectory.steps = 17;
  const SolutionFile back = parse_solution(format_solution(file_of(trajectory)), "memory", ".");
  const auto& read = std::get<RodTrajectory>(back.solution);
  EXPECT_EQ(read.t, trajectory.t);
  ASSERT_EQ(read.snapshots.size(), trajectory.snapshots.size());
  for (std::size_t k = 0; k < read.snapshots.size(); ++k) {
    EXPECT_EQ(read.snapshots[k].s, trajectory.snapshots[k].s);
    EXPECT_EQ(read.snapshots[k].position, trajectory.snapshots[k].position);
  }
  EXPECT_EQ(read.steps, 17u);
  EXPECT_EQ(read.method, file_of(trajectory).solver);
}

// A file with positions only, on a circle of radius R (theta = s/R, kappa = 1/R), on a NON-uniform
// grid: the derived theta and kappa converge at second order, and the file says what was derived.
TEST(SolutionFile, DerivesThetaAndKappaAtSecondOrder) {
  const double R = 0.37, L = 2.1;
  std::vector<double> theta_error, kappa_error;
  for (int n : {16, 32, 64, 128}) {
    std::string sv, x, y;
    for (int i = 0; i <= n; ++i) {
      const double u = double(i) / n;
      const double arclength = L * (u + 0.05 * std::sin(std::numbers::pi * u));  // graded, monotone
      const auto append = [i](std::string& list, double value) {
        if (i > 0) list.push_back(',');
        list.append(shortest(value));
      };
      append(sv, arclength);
      append(x, R * std::sin(arclength / R));
      append(y, R * (1.0 - std::cos(arclength / R)));
    }
    const std::string text = R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": )" +
                             std::to_string(n) + R"(}, "planar_rod": {"nodes": {"s": [)" + sv + "], \"x\": [" + x +
                             "], \"y\": [" + y + "]}}}";
    const SolutionFile file = parse_solution(text, "circle", ".");
    const auto& rod = std::get<PlanarRodSolution>(file.solution);
    double worst_theta = 0.0, worst_kappa = 0.0;
    for (std::size_t i = 0; i < rod.s.size(); ++i) {
      worst_theta = std::max(worst_theta, std::abs(rod.theta[i] - rod.s[i] / R));
      worst_kappa = std::max(worst_kappa, std::abs(rod.kappa[i] - 1.0 / R));
    }
    theta_error.push_back(worst_theta);
    kappa_error.push_back(worst_kappa * R);
    ASSERT_EQ(file.derived.size(), 2u);
    EXPECT_NE(file.derived[0].find("theta"), std::string::npos);
    ASSERT_EQ(file.missing.size(), 1u);  // no EI, no force: no H
    EXPECT_NE(file.missing[0].find("Noether"), std::string::npos);
    EXPECT_TRUE(rod.axial_force.empty());
  }
  for (std::size_t i = 1; i < theta_error.size(); ++i) {
    // Second order: the error falls by 4 per halving; 3.5 leaves room for the graded grid's
    // pre-asymptotic terms, and a first-order stencil (ratio 2) fails it.
    EXPECT_GT(theta_error[i - 1] / theta_error[i], 3.5) << i;
    EXPECT_GT(kappa_error[i - 1] / kappa_error[i], 3.5) << i;
  }
  // Magnitude: the leading term of a three-point stencil is h^2 f'''/6 ~ (L/n)^2 / (6 R^2) for theta
  // and one derivative more for kappa; measured 2e-4 and 2e-3 at n = 128; bounded by 4x that.
  EXPECT_LT(theta_error.back(), 1e-3);
  EXPECT_LT(kappa_error.back(), 1e-2);
}

struct Malformed {
  std::string text;
  std::string message;  // a fragment the InputError must contain
};

std::string planar(const std::string& nodes, const std::string& extra = "") {
  return R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 2}, "planar_rod": {)" +
         extra + R"("nodes": {)" + nodes + "}}}";
}

std::string rod_trajectory(const std::string& samples) {
  return R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 1}, "rod_trajectory": {)"
         R"("samples": {)" + samples + "}}}";
}

std::string spatial(const std::string& body) {
  return R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 1}, "spatial_rod": {)" +
         body + "}}";
}

const std::string kNodes = R"("s": [0, 0.5, 1], "x": [0, 0.5, 1], "y": [0, 0, 0])";

TEST(SolutionFile, MalformedFilesNameWhereAndWhat) {
  const std::vector<Malformed> cases = {
      {"{ \"format\": ", "not valid JSON at line 1"},
      {"{\n\"format\": \"rodvv-solution\",\n\"version\": 1,,\n}", "not valid JSON at line 3"},
      {"[1, 2]", "$: expected an object, got array"},
      {R"({"format": "other", "version": 1})", "$.format: expected \"rodvv-solution\""},
      {R"({"format": "rodvv-solution", "version": 2})", "format version 2 is not one this rodvv reads"},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "colour": 1})", "unknown field \"colour\""},
      {R"({"format": "rodvv-solution", "version": 1, "resolution": {"N": 2}})", "missing required field \"case\""},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 2, "dt": 1}})",
       "expected an object with one entry"},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": -2}})",
       "$.resolution.N: expected a number > 0, got -2"},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 2}})",
       "expected exactly one solution"},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "parameters": {"L": "long"}, "resolution": {"N": 2}})",
       "$.parameters.L: expected a finite number, got the string \"long\""},
      {planar(R"("s": [0, 0.5, 1], "x": [0, null, 1], "y": [0, 0, 0])"),
       "$.planar_rod.nodes.x[1]: expected a finite number, got null"},
      {planar(R"("s": [0, 0.5, 1], "x": [0, 0.5], "y": [0, 0, 0])"), "column \"x\" has 2 values but \"s\" has 3"},
      {planar(R"("s": [0, 1, 0.5], "x": [0, 0.5, 1], "y": [0, 0, 0])"), "\"s\" must increase strictly"},
      {planar(R"("s": [0.1, 0.5, 1], "x": [0, 0.5, 1], "y": [0, 0, 0])"), "the arclength must start at 0"},
      {planar(R"("s": [0, 0.5, 1], "y": [0, 0, 0])"), "missing the required array \"x\""},
      {planar(R"("s": [0, 0.5, 1], "x": [0, 0.5, 1], "y": [0, 0, 0], "theat": [0, 0, 0])"),
       "unknown field \"theat\""},
      {planar(kNodes + R"(, "force_x": [0, 0, 0])"), "force_x and force_y come together"},
      {planar(kNodes, R"("bending_stiffness": 0, )"), "$.planar_rod.bending_stiffness: expected a number > 0"},
      {planar(kNodes + R"(, "bending_stiffness": [1, -1, 1])"), "bending_stiffness[1] = -1: must be > 0"},
      {planar(kNodes + R"(, "bending_stiffness": [1, 1, 1])", R"("bending_stiffness": 1, )"), "given twice"},
      {planar(kNodes, R"("length": 2, )"), "length 2 differs from the last arclength"},
      {planar(kNodes, R"("nodes_csv": "n.csv", )"), "expected exactly one of \"nodes\""},
      {planar(kNodes, R"("iterations": 1.5, )"), "expected a whole number >= 0, got 1.5"},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 2}, "cpu_seconds": -1})",
       "$.cpu_seconds: expected a time >= 0"},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 2}, "planar_rod": {"nodes": {}},
          "trajectory": {}})",
       "expected exactly one solution"},
      {spatial(R"("vertices": {"s": [0, 1], "position_x": [0, 1], "position_y": [0, 0]})"),
       "position_x, position_y and position_z come together; 2 of them given"},
      {spatial(R"("vertices": {"s": [0, 1], "position_x": [0, 1], "position_y": [0, 0], "position_z": [0, 0],
                   "n0_x": [1, 1], "n0_y": [0, 0], "n0_z": [0, 0]})"),
       "a frame needs the three directors n0, n1, n2"},
      {spatial(R"("vertices": {"s": [0, 1], "position_x": [0, 1], "position_y": [0, 0], "position_z": [0, 0]},
                 "stations": {"s": [0.25, 0.75], "position_x": [0.25, 0.75], "position_y": [0, 0], "position_z": [0, 0]})"),
       "missing the frames n0_x .. n2_z"},
      {spatial(R"("vertices": {"s": [0, 1], "position_x": [0, 1], "position_y": [0, 0], "position_z": [0, 0],
                   "strain_u_0": [0, 0]})"),
       "unknown field \"strain_u_0\""},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"dt": 0.1}, "trajectory":
          {"samples": {"t": [0, 0.1, 0.1], "theta": [0, 1, 2], "theta_dot": [0, 1, 2]}}})",
       "\"t\" must increase strictly, but t[2] = 0.1 follows t[1] = 0.1"},
      {R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"dt": 0.1}, "trajectory":
          {"samples": {"t": [0, 0.1], "theta": [0, 1]}}})",
       "missing the required array \"theta_dot\""},
      {rod_trajectory(R"("t": [0, 0, 0.2, 0.2, 0.1, 0.1], "s": [0, 1, 0, 1, 0, 1], "position_x": [0, 1, 0, 1, 0, 1],
                         "position_y": [0, 0, 0, 0, 0, 0], "position_z": [0, 0, 0, 0, 0, 0])"),
       "row 4: t = 0.1 follows the snapshot at t = 0.2"},
      {rod_trajectory(R"("t": [0, 0, 0.1, 0.1, 0.2], "s": [0, 1, 0, 1, 0], "position_x": [0, 1, 0, 1, 0],
                         "position_y": [0, 0, 0, 0, 0], "position_z": [0, 0, 0, 0, 0])"),
       "rows 4 .. 4: the snapshot at t = 0.2 has 1 vertex; at least 2 are needed"},
      {rod_trajectory(R"("t": [0, 0, 0, 0.1, 0.1], "s": [0, 1, 0.5, 0, 1], "position_x": [0, 1, 0, 1, 0],
                         "position_y": [0, 0, 0, 0, 0], "position_z": [0, 0, 0, 0, 0])"),
       "row 2: s = 0.5 follows s = 1 in the snapshot at t = 0"},
      {rod_trajectory(R"("t": [0, 0, 0.1, 0.1], "s": [0, 1, 0.2, 1], "position_x": [0, 1, 0, 1],
                         "position_y": [0, 0, 0, 0], "position_z": [0, 0, 0, 0])"),
       "row 2: s = 0.2: the arclength of the snapshot at t = 0.1 must start at 0"},
      {rod_trajectory(R"("t": [0, 0], "s": [0, 1])"), "missing the required arrays position_x, position_y, position_z"},
      {rod_trajectory(R"("t": [0, 0], "s": [0, 1], "position_x": [0, 1], "position_y": [0, 0], "position_z": [0, 0],
                         "n0_x": [1, 1])"),
       "unknown field \"n0_x\""},
  };
  for (const auto& c : cases) {
    try {
      parse_solution(c.text, "bad.json", ".");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const InputError& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find("bad.json"), std::string::npos) << what;
      EXPECT_NE(what.find(c.message), std::string::npos) << "expected \"" << c.message << "\" in: " << what;
    }
  }
}

class CsvNodes : public ::testing::Test {
 protected:
  // One directory per process: CTest runs this fixture's tests side by side (-j), and a shared directory
  // let one test's TearDown delete the other's files mid-read (seen in CI).
  std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("rodvv_test_csv_nodes-" + std::to_string(::getpid()));
  void SetUp() override { std::filesystem::create_directories(directory); }
  void TearDown() override { std::filesystem::remove_all(directory); }
  SolutionFile read_with_csv(const std::string& csv) {
    std::ofstream(directory / "nodes.csv") << csv;
    const std::string json = R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 2},
        "planar_rod": {"nodes_csv": "nodes.csv", "bending_stiffness": 2.5}})";
    std::ofstream(directory / "run.json") << json;
    return read_solution_file(directory / "run.json");
  }
  void expect_rejected(const std::string& csv, const std::string& message) {
    try {
      read_with_csv(csv);
      ADD_FAILURE() << "accepted: " << csv;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos)
          << "expected \"" << message << "\" in: " << error.what();
    }
  }
};

TEST_F(CsvNodes, ReadsColumnsBesideTheJson) {
  const SolutionFile file = read_with_csv(
      "# written by a test\ns, x, y, force_x, force_y\n0, 0, 0, -1, 0\n0.5, 0.5, 0, -1, 0\r\n1, +1, 0, -1, 0\n\n");
  const auto& rod = std::get<PlanarRodSolution>(file.solution);
  EXPECT_EQ(rod.x, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(rod.bending_stiffness, (std::vector<double>{2.5, 2.5, 2.5}));
  EXPECT_EQ(rod.axial_force, (std::vector<double>{-1.0, -1.0, -1.0}));  // n.t derived (theta = 0)
  EXPECT_TRUE(file.missing.empty());
}

TEST_F(CsvNodes, MalformedCsvNamesTheLine) {
  expect_rejected("s,x,y\n0,0,0\n0.5,abc,0\n1,1,0\n", "nodes.csv:3: column \"x\": expected a finite number, got \"abc\"");
  expect_rejected("s,x,y\n0,0,0\n0.5,0.5\n", "nodes.csv:3: 2 fields, but the header names 3 columns");
  expect_rejected("s,x,why\n", "nodes.csv:1: unknown column \"why\"");
  expect_rejected("s,x,x\n", "column \"x\" appears twice");
  expect_rejected("s,x,y\n0,0,0\n0.5,inf,0\n", "expected a finite number, got \"inf\"");
  expect_rejected("", "no header row");
  std::filesystem::remove(directory / "nodes.csv");
  const std::string json = R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 2},
      "planar_rod": {"nodes_csv": "absent.csv"}})";
  std::ofstream(directory / "run.json") << json;
  EXPECT_THROW(read_solution_file(directory / "run.json"), InputError);
  EXPECT_THROW(read_solution_file(directory / "no-such.json"), InputError);
}

}  // namespace
}  // namespace rodvv::solution_files
