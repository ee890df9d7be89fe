// The sweep file parser and the grid (doc/sweep.md).

#include "tools/sweep/SweepSpec.hpp"
#include "tools/sweep/SweepGrid.hpp"

#include <gtest/gtest.h>

using namespace stella::sweep;

namespace {

const char* const sample = R"(# Hertz: error against time
study = hertz.export   # the template
comm = template.comm
repeats = 5
error = p0 h
mesh = gmsh hertz.geo -2 -setnumber H {H} -o {mesh}
mesh_unit = 20
mesh_size = H

[vary]
H = 1.0, 0.5

[series]
CONTRAINTE: ALGO = {'ALGO_CONT': 'CONTRAINTE'}
PENALISATION 1e5: ALGO = {'ALGO_CONT': 'PENALISATION', 'E_N': 1.0e5}; NOTE = 'a # in quotes'
)";

std::string errorOf(const std::string& text) {
  try {
    parseSweepFile(text, "/s/study.sweep");
  } catch (const SweepError& e) {
    return e.what();
  }
  return "no error";
}

} // namespace

TEST(SweepSpec, ParsesKeysVaryAndSeries) {
  const SweepSpec s = parseSweepFile(sample, "/s/study.sweep");
  EXPECT_EQ(s.study, "/s/hertz.export");
  EXPECT_EQ(s.comm, "/s/template.comm");
  EXPECT_EQ(s.repeats, 5);
  EXPECT_EQ(s.error, "p0 h");
  EXPECT_EQ(s.meshUnit, 20);
  EXPECT_EQ(s.meshSize, "H");
  ASSERT_EQ(s.vary.size(), 1u);
  EXPECT_EQ(s.vary[0].values, (std::vector<std::string>{"1.0", "0.5"}));
  ASSERT_EQ(s.series.size(), 2u);
  EXPECT_EQ(s.series[1].name, "PENALISATION 1e5");
  ASSERT_EQ(s.series[1].settings.size(), 2u);
  EXPECT_EQ(s.series[1].settings[0].second, "{'ALGO_CONT': 'PENALISATION', 'E_N': 1.0e5}");
  EXPECT_EQ(s.series[1].settings[1].second, "'a # in quotes'");
  EXPECT_EQ(s.series[1].line, 15);
  EXPECT_NO_THROW(validate(s));
}

TEST(SweepSpec, DefaultsToThreeRepeats) {
  EXPECT_EQ(parseSweepFile("study = a.export\n", "/s/x.sweep").repeats, 3);
}

TEST(SweepSpec, SplitsOutsideQuotesAndBrackets) {
  EXPECT_EQ(splitTopLevel("'a,b', (1, 2), {'k': [3, 4]}, 5", ','),
            (std::vector<std::string>{"'a,b'", "(1, 2)", "{'k': [3, 4]}", "5"}));
}

TEST(SweepSpec, RefusesBadLinesWithTheirLocation) {
  EXPECT_EQ(
      errorOf("study = a.export\nrepeat = 3\n"),
      "/s/study.sweep:2: unknown key 'repeat' (known: study, comm, repeats, timeout, time, error, mesh, "
      "mesh_unit, mesh_size, series; parameters go under [vary])");
  EXPECT_EQ(errorOf("study = a.export\nrepeats = 0\n"),
            "/s/study.sweep:2: repeats expects a positive integer, got '0'");
  EXPECT_EQ(errorOf("study = a.export\n[vary]\nN = 1,\n"),
            "/s/study.sweep:3: an empty value in the list of N");
  EXPECT_EQ(errorOf("study = a.export\n[vary]\nN = 1\nN = 2\n"),
            "/s/study.sweep:4: parameter N is already varied at line 3");
  EXPECT_EQ(errorOf("study = a.export\n[series]\nGCP ALGO = 1\n"),
            "/s/study.sweep:3: a series is 'NAME: PARAMETER = value; ...', got 'GCP ALGO = 1'");
  EXPECT_EQ(errorOf("study = a.export\ntime = user\n"), "/s/study.sweep:2: time is wall or cpu, got 'user'");
  EXPECT_EQ(errorOf("[grid]\n"), "/s/study.sweep:1: unknown section '[grid]' (sections: [vary], [series])");
  EXPECT_EQ(errorOf("repeats = 3\n"),
            "/s/study.sweep: no 'study = <file>.export' line: the sweep needs the study it varies");
}

TEST(SweepSpec, ValidatesCrossReferences) {
  SweepSpec s =
      parseSweepFile("study = a.export\nmesh = gmsh a.geo -o {mesh}\n[vary]\nN = 1, 2\n", "/s/x.sweep");
  EXPECT_THROW(validate(s), SweepError); // no mesh_unit
  s.meshUnit = 20;
  EXPECT_NO_THROW(validate(s));
  s.meshSize = "H";
  EXPECT_THROW(validate(s), SweepError); // H is not varied
}

TEST(SweepSpec, VaryOptionAddsOrReplaces) {
  SweepSpec s = parseSweepFile("study = a.export\n[vary]\nN = 1, 2\n", "/s/x.sweep");
  addVary(s, "N=4,8,16");
  addVary(s, "ALGO='GCP','CONTRAINTE'");
  ASSERT_EQ(s.vary.size(), 2u);
  EXPECT_EQ(s.vary[0].values, (std::vector<std::string>{"4", "8", "16"}));
  EXPECT_EQ(s.vary[1].values, (std::vector<std::string>{"'GCP'", "'CONTRAINTE'"}));
  EXPECT_THROW(addVary(s, "N"), SweepError);
}

TEST(SweepGrid, CrossesSeriesWithVaryFirstParameterSlowest) {
  const SweepSpec s = parseSweepFile(
      "study = a.export\n[vary]\nH = 1, 2\nQ = 'a', 'b'\n[series]\nS1: X = 1\nS2: X = 2; Y = 3\n",
      "/s/x.sweep");
  EXPECT_EQ(parameterColumns(s), (std::vector<std::string>{"H", "Q", "X", "Y"}));
  const auto points = expandGrid(s);
  ASSERT_EQ(points.size(), 8u);
  EXPECT_EQ(points[0].label, "S1 H=1 Q=a");
  EXPECT_EQ(points[1].label, "S1 H=1 Q=b");
  EXPECT_EQ(points[2].label, "S1 H=2 Q=a");
  EXPECT_EQ(points[4].series, "S2");
  EXPECT_EQ(points[4].settings, (std::vector<Setting>{{"H", "1"}, {"Q", "'a'"}, {"X", "2"}, {"Y", "3"}}));
  EXPECT_EQ(points[0].settings[3], (Setting{"Y", ""}));
  EXPECT_EQ(points[7].index, 8);
}

TEST(SweepGrid, SeriesParameterNamesTheSeries) {
  const SweepSpec s = parseSweepFile(
      "study = a.export\nseries = ALGO\n[vary]\nALGO = 'GCP', 'CONTRAINTE'\nN = 4\n", "/s/x.sweep");
  const auto points = expandGrid(s);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1].series, "CONTRAINTE");
  EXPECT_EQ(points[1].label, "CONTRAINTE N=4");
}

TEST(SweepGrid, WithoutSeriesTheLabelIsTheValues) {
  SweepSpec s = parseSweepFile("study = a.export\n", "/s/x.sweep");
  addVary(s, "N=4,8");
  const auto points = expandGrid(s);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1].series, "study");
  EXPECT_EQ(points[1].label, "N=8");
}

TEST(SweepGrid, SubstitutesTopLevelAssignmentsOnly) {
  const std::string comm = "N = 4\nNN = 7\nE_N=1.0  # comment\n  N = 5\nif N == 4:\n    pass\n";
  std::set<std::string> used;
  const std::string out = substituteAssignments(comm, {{"N", "16"}, {"E_N", "1e6"}, {"M", "3"}}, used);
  EXPECT_EQ(out, "N = 16  # set by stella sweep\nNN = 7\nE_N = 1e6  # set by stella sweep\n  N = 5\n"
                 "if N == 4:\n    pass\n");
  EXPECT_EQ(used, (std::set<std::string>{"E_N", "N"}));
}

TEST(SweepGrid, SubstitutesOnlyBeforeDebut) {
  // MESH after DEBUT() is a concept, not the parameter: a sweep must never replace it.
  const std::string comm = "MESH = 'a.msh'\nDEBUT()\nMESH = LIRE_MAILLAGE(UNITE=20)\n";
  std::set<std::string> used;
  EXPECT_EQ(substituteAssignments(comm, {{"MESH", "'b.msh'"}}, used),
            "MESH = 'b.msh'  # set by stella sweep\nDEBUT()\nMESH = LIRE_MAILLAGE(UNITE=20)\n");
  used.clear();
  EXPECT_EQ(substituteAssignments("DEBUT()\nN = 4\n", {{"N", "8"}}, used), "DEBUT()\nN = 4\n");
  EXPECT_TRUE(used.empty());
}

TEST(SweepGrid, SubstitutesTheMeshCommand) {
  std::set<std::string> used;
  EXPECT_EQ(substituteBraces("gmsh a.geo -setnumber H {H} -o {mesh}", {{"H", "0.5"}}, "/m/1.msh", used),
            "gmsh a.geo -setnumber H 0.5 -o /m/1.msh");
  EXPECT_EQ(used, (std::set<std::string>{"H"}));
  EXPECT_THROW(substituteBraces("gmsh -setnumber N {N}", {{"H", "0.5"}}, "", used), SweepError);
}

TEST(SweepSpec, ExternalSeriesIsACommandWritingOut) {
  const auto spec = parseSweepFile("study = s.export\n[series]\nGCP: ALGO = 'GCP'\n"
                                   "CalculiX: ! python3 ccx_point.py {H} {out}  # run per point\n",
                                   "/s/study.sweep");
  ASSERT_EQ(spec.series.size(), 2U);
  EXPECT_TRUE(spec.series[0].command.empty());
  EXPECT_EQ(spec.series[1].name, "CalculiX");
  EXPECT_EQ(spec.series[1].command, "python3 ccx_point.py {H} {out}");
  EXPECT_TRUE(spec.series[1].settings.empty());
  EXPECT_EQ(errorOf("study = s.export\n[series]\nCalculiX: ! ccx job\n"),
            "/s/study.sweep:3: the command of external series 'CalculiX' must write its results to {out}, "
            "e.g. '! python3 ccx_point.py {H} {out}'");
}
