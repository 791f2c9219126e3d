// `rodvv problem`'s data (harness/problem_data.hpp): what the manufactured cases hand another solver must
// pose their problem. Checked through the equilibrium equations on the table alone, by finite differences
// independent of the references that made it: the 3-D force density integrates to the drop of the internal
// force (Simpson, O(h^4)) and the couple density closes the moment balance m' + t x n + c = 0 (central
// differences, O(h^2)); the planar force density is -grad V of the stated potential, n' = grad V.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/harness/registry.hpp"

namespace rodvv::harness {
namespace {

struct Table {
  std::map<std::string, double> values;
  std::map<std::string, std::vector<double>> columns;
  const std::vector<double>& operator[](const std::string& name) const { return columns.at(name); }
  Vec3 value(const std::string& name) const {
    return {values.at(name + "_x"), values.at(name + "_y"), values.at(name + "_z")};
  }
  Vec3 vector(const std::string& name, std::size_t i, const char* axes = "xyz") const {
    return {columns.at(name + "_" + axes[0])[i], columns.at(name + "_" + axes[1])[i], columns.at(name + "_" + axes[2])[i]};
  }
};

Table table_of(const std::string& case_name, std::size_t intervals) {
  const Case& c = *default_registry().find(case_name);
  const ProblemData data = c.problem_data(c.info.parameters, intervals);
  Table table;
  for (const auto& [name, value] : data.values) table.values[name] = value;
  EXPECT_EQ(data.columns.front(), "s");
  EXPECT_EQ(data.rows.size(), intervals + 1);
  for (std::size_t j = 0; j < data.columns.size(); ++j)
    for (const auto& row : data.rows) table.columns[data.columns[j]].push_back(row[j]);
  EXPECT_FALSE(data.description.empty());
  return table;
}

// Largest violation of the 3-D balance laws on the table, over the scales of n and m.
struct Balance {
  double force = 0.0, moment = 0.0;
};
Balance balance_3d(const Table& t) {
  const auto& s = t["s"];
  const std::size_t n = s.size() - 1;
  const double h = s[1] - s[0];
  double force_scale = 0.0, moment_scale = 0.0;
  for (std::size_t i = 0; i <= n; ++i) {
    force_scale = std::max(force_scale, t.vector("force", i).norm());
    moment_scale = std::max(moment_scale, t.vector("moment", i).norm());
  }
  Balance b;
  // Simpson over [0, 0.3 L] (0.3 n even): over the whole rod the symmetric nodes integrate the fields' odd
  // parts about L/2 exactly, which would hide the O(h^4).
  const std::size_t m = 3 * n / 10;
  Vec3 integral = Vec3::Zero();
  for (std::size_t i = 0; i <= m; ++i)
    integral += (i == 0 || i == m ? 1.0 : i % 2 ? 4.0 : 2.0) * h / 3.0 * t.vector("force_density", i);
  b.force = (integral - (t.vector("force", 0) - t.vector("force", m))).norm() / force_scale;
  for (std::size_t i = 1; i < n; ++i) {
    const Vec3 dm = (t.vector("moment", i + 1) - t.vector("moment", i - 1)) / (2.0 * h);
    const Vec3 tangent = t.vector("n0", i);
    const Vec3 residual = dm + tangent.cross(t.vector("force", i)) + t.vector("couple_density", i);
    b.moment = std::max(b.moment, residual.norm() * t.values.at("length") / moment_scale);
  }
  return b;
}

TEST(ProblemData, ManufacturedLoadsCloseTheBalanceLaws3d) {
  for (const char* name : {"rod3d/manufactured", "superhelix/manufactured", "superhelix/clothoid-manufactured"}) {
    const Table coarse = table_of(name, 100), fine = table_of(name, 200);
    const Balance a = balance_3d(coarse), b = balance_3d(fine);
    std::cout << "[ summary  ] " << name << ": force balance " << a.force << ", " << b.force << "; moment balance "
              << a.moment << ", " << b.moment << " (100, 200 intervals)\n";
    // Simpson O(h^4), central differences O(h^2): measured ratios 16.0 and 4.0 (3.1e-9 -> 1.9e-10 on the nodal
    // rod's problem, 1.9e-7 -> 1.2e-8 on the couple-free one; moments 2.0e-3 -> 4.9e-4).
    EXPECT_LT(b.force, 1e-6) << name;
    EXPECT_GT(a.force / b.force, 12.0) << name;
    EXPECT_LT(b.moment, 1e-3) << name;
    EXPECT_NEAR(a.moment / b.moment, 4.0, 0.4) << name;
    // The tip loads are the internal force and moment at s = L (integrated to L in one pass, the stations in
    // 200: round-off apart, measured <= 1e-14 of their size); the clamp is the first station's pose.
    const std::size_t last = fine["s"].size() - 1;
    EXPECT_EQ(fine["s"][last], fine.values.at("length"));
    const Vec3 tip_force = fine.value("tip_force"), tip_moment = fine.value("tip_moment");
    EXPECT_LE((tip_force - fine.vector("force", last)).norm(), 1e-12 * tip_force.norm()) << name;
    EXPECT_LE((tip_moment - fine.vector("moment", last)).norm(), 1e-12 * tip_moment.norm()) << name;
    EXPECT_LT((fine.value("root_position") - fine.vector("position", 0)).norm(), 1e-15 * fine.values.at("length"));
    EXPECT_LT((fine.value("root_n1") - fine.vector("n1", 0)).norm(), 1e-14);
  }
  // The couple-free rod asks for no distributed couple.
  const Table free = table_of("superhelix/manufactured", 10);
  EXPECT_EQ(free.values.at("couple_free"), 1.0);
  for (double c : free["couple_density_x"]) EXPECT_EQ(c, 0.0);
}

TEST(ProblemData, PlanarForceIsTheGradientOfTheStatedPotential) {
  const Table t = table_of("elastica/manufactured/polygon", 200);
  const auto& s = t["s"];
  const double h = s[1] - s[0], a = t.values.at("field_xx"), b = t.values.at("field_xy"), c = t.values.at("field_y");
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) scale = std::max(scale, std::hypot(t["force_x"][i], t["force_y"][i]));
  for (std::size_t i = 1; i + 1 < s.size(); ++i) {
    const double x = t["x"][i], y = t["y"][i];
    // n' = -f = grad V, V = 1/2 a x^2 + b x y + c y.
    const double dnx = (t["force_x"][i + 1] - t["force_x"][i - 1]) / (2.0 * h) - (a * x + b * y);
    const double dny = (t["force_y"][i + 1] - t["force_y"][i - 1]) / (2.0 * h) - (b * x + c);
    worst = std::max(worst, std::hypot(dnx, dny) * t.values.at("length") / scale);
  }
  EXPECT_LT(worst, 1e-4);
  EXPECT_EQ(t["force_x"].back(), t.values.at("tip_force_x"));
  EXPECT_EQ(t["moment"].back(), t.values.at("tip_moment"));
}

TEST(ProblemData, OnlyTheCasesThatNeedItHaveIt) {
  std::vector<std::string> with;
  for (const Case& c : default_registry().cases())
    if (c.problem_data) with.push_back(c.info.name);
  std::sort(with.begin(), with.end());
  EXPECT_EQ(with, (std::vector<std::string>{"elastica/manufactured/arcs", "elastica/manufactured/polygon",
                                            "rod3d/manufactured", "superhelix/clothoid-manufactured",
                                            "superhelix/manufactured"}));
}

}  // namespace
}  // namespace rodvv::harness
