// The message-file reader (errors against hand-computed values), the Pareto front, the CSV.

#include "tools/sweep/SweepTable.hpp"
#include "tools/sweep/MessReport.hpp"
#include "tools/sweep/SweepSpec.hpp"

#include <gtest/gtest.h>

using namespace stella::sweep;

// Lines as stella writes them (StatNonLine.cpp, PhaseTimes.cpp, ContactConstraint.cpp, TEST_RESU).
const char* const message =
    R"(   step 1 INST 0.5: converged in 3 iteration(s), RESI_GLOB_RELA = 1.000e-07, stored as NUME_ORDRE 1
   contact: 2 geometric iteration(s), 9 contact iteration(s)
   phases (s): numbering 0.002, assembly 0.042, factorisation 0.017 (1 analysis), solve 0.018, post 0.000, other 0.004; total 0.082, outside factorisation and solve 57.2 %
   step 2 INST 1: converged in 4 iteration(s), RESI_GLOB_RELA = 2.328e-14, 1 line search iteration(s), stored as NUME_ORDRE 2
   contact: 1 geometric iteration(s), 3 contact iteration(s)
   phases (s): numbering 0.001, assembly 0.010, factorisation 0.020 (1 analysis), solve 0.003, post 0.001; total 0.035, outside factorisation and solve 34.3 %
---- RESULTAT         NUME_ORDRE       NOM_CHAM         TYPE_TEST        NOM_CMP
     RESU             1                CONT_NOEU        MAX              RN
     REFERENCE        p0 h             VALE_REFE          VALE_CALC          ERREUR           TOLE
 OK  NON_REGRESSION   p0 h             1390.557           1390.5569446812951 4E-06%           0.0001%
 OK  ANALYTIQUE       p0 h             1388.9087          1390.5569446812951 0.12%            2%

---- RESULTAT         NUME_ORDRE       NOM_CHAM         NOM_CMP          NOEUD
     RESU             1                DEPL             DX               N9
     REFERENCE        XXXX             VALE_REFE            VALE_CALC            ERREUR           TOLE
NOOK ANALYTIQUE       XXXX             9.533333333333335E-4 9.53314478122818E-4  0.002%           1E-06%
 OK  SOURCE_EXTERNE   XXXX             0.0                  -2.5E-3              0.0025           0.001

------------------------------------------------------------
--- DIAGNOSTIC JOB : NOOK_TEST_RESU
------------------------------------------------------------
)";

TEST(MessReport, ReadsIterationsPhasesAndDiagnostic) {
  const MessReport r = parseMessage(message);
  EXPECT_EQ(r.diagnostic, "NOOK_TEST_RESU");
  EXPECT_EQ(r.steps, 2);
  EXPECT_EQ(r.newtonIterations, 7);
  EXPECT_EQ(r.geometricIterations, 3);
  EXPECT_EQ(r.contactIterations, 12);
  EXPECT_DOUBLE_EQ(r.phases.assembly, 0.052);
  EXPECT_DOUBLE_EQ(r.phases.factorisation, 0.037);
  EXPECT_DOUBLE_EQ(r.phases.other, 0.004);
  EXPECT_DOUBLE_EQ(r.phases.total, 0.117);
}

TEST(MessReport, ErrorsOfReferenceLinesAgainstHandComputedValues) {
  const MessReport r = parseMessage(message);
  ASSERT_EQ(r.tests.size(), 3u); // the NON_REGRESSION line is no reference
  EXPECT_EQ(r.tests[0].name, "p0 h");
  // |1390.5569446812951 - 1388.9087| / 1388.9087 = 1.6482446812951 / 1388.9087 = 1.18671924e-3
  EXPECT_NEAR(r.tests[0].error, 1.18671924e-3, 1e-11);
  // no LEGENDE: named by the tested field; |9.53314478122818e-4 - 9.533333e-4| / 9.533333e-4
  EXPECT_EQ(r.tests[1].name, "RESU 1 DEPL DX N9");
  EXPECT_NEAR(r.tests[1].error, 1.9778193e-05, 1e-12);
  EXPECT_DOUBLE_EQ(r.tests[2].reference, 0.0);
  EXPECT_DOUBLE_EQ(r.tests[2].error, 2.5e-3); // reference 0: the absolute difference
  EXPECT_EQ(r.tests[2].name, "RESU 1 DEPL DX N9 #2");
}

TEST(MessReport, RelativeError) {
  EXPECT_DOUBLE_EQ(relativeError(101.0, 100.0), 0.01);
  EXPECT_DOUBLE_EQ(relativeError(-99.0, -100.0), 0.01);
  EXPECT_DOUBLE_EQ(relativeError(0.5, 0.0), 0.5);
}

TEST(Pareto, KeepsOnlyPointsNothingBeatsOnBoth) {
  //            0     1     2     3     4     5 (failed)  6 (ties 1 on time, worse error)
  const std::vector<double> time{1.0, 2.0, 3.0, 2.5, 0.5, 0.1, 2.0};
  const std::vector<double> error{0.1, 0.01, 0.001, 0.05, 0.5, 1e-9, 0.02};
  const std::vector<bool> eligible{true, true, true, true, true, false, true};
  // 3 is beaten by 1 (faster and more accurate); 5 would beat everything but failed.
  EXPECT_EQ(paretoFront(time, error, eligible), (std::vector<std::size_t>{4, 0, 1, 2}));
}

TEST(Pareto, EqualPointsBothStay) {
  EXPECT_EQ(paretoFront({1.0, 1.0}, {0.1, 0.1}, {true, true}), (std::vector<std::size_t>{0, 1}));
}

TEST(SweepTable, MarksTheFrontFromTheColumns) {
  Table t{{"label", "finished", "wall_s", "error"},
          {{"a", "yes", "1", "0.1"},
           {"b", "yes", "2", "0.2"},
           {"c", "no", "0.1", ""},
           {"d", "yes", "3", "0.01"}}};
  const auto front = markParetoFront(t);
  EXPECT_EQ(front, (std::vector<std::size_t>{0, 3}));
  EXPECT_EQ(t.at(0, "pareto"), "yes");
  EXPECT_EQ(t.at(1, "pareto"), "");
  const std::string md = toMarkdown(t, front);
  EXPECT_NE(md.find("- error 0.1: **a**, 1 s\n- error 0.01: **d**, 3 s\n"), std::string::npos) << md;
}

TEST(SweepTable, NamesEachTestWhenTheErrorsAreOfSeveral) {
  Table t{{"label", "finished", "wall_s", "error", "error_of"},
          {{"a", "yes", "1", "0.1", "u_r(a)"}, {"b", "yes", "2", "0.01", "u_r(b)"}}};
  const auto front = markParetoFront(t);
  const std::string md = toMarkdown(t, front);
  EXPECT_NE(md.find("Pareto front (largest error of each run against"), std::string::npos) << md;
  EXPECT_NE(md.find("- error 0.1 (u_r(a)): **a**, 1 s\n- error 0.01 (u_r(b)): **b**, 2 s\n"),
            std::string::npos)
      << md;
}

TEST(SweepTable, CsvRoundTripsQuotesAndCommas) {
  Table t{{"label", "ALGO"}, {{"GCP, fine", "{'ALGO_CONT': \"GCP\"}"}, {"plain", ""}}};
  const std::string csv = toCsv(t);
  EXPECT_EQ(csv, "label,ALGO\n\"GCP, fine\",\"{'ALGO_CONT': \"\"GCP\"\"}\"\nplain,\n");
  const Table back = fromCsv(csv);
  EXPECT_EQ(back.header, t.header);
  EXPECT_EQ(back.rows, t.rows);
  EXPECT_THROW(fromCsv("a,b\n1\n"), SweepError);
}

TEST(MessReport, ExternalResultLinesAgainstHandComputedErrors) {
  const auto r = parseExternalResult("# written by ccx_point.py\n\n  3042.5 3000 p0 h \n-2 0 gap\n");
  ASSERT_EQ(r.tests.size(), 2U);
  EXPECT_EQ(r.tests[0].name, "p0 h");
  EXPECT_DOUBLE_EQ(r.tests[0].computed, 3042.5);
  EXPECT_DOUBLE_EQ(r.tests[0].reference, 3000.0);
  EXPECT_NEAR(r.tests[0].error, 42.5 / 3000.0, 1e-15);
  EXPECT_DOUBLE_EQ(r.tests[1].error, 2.0); // a reference of 0: the absolute difference
  EXPECT_TRUE(r.diagnostic.empty());
  try {
    parseExternalResult("1 2 ok\n1.0 p0\n");
    FAIL() << "a line without its reference was accepted";
  } catch (const SweepError& e) {
    EXPECT_STREQ(e.what(), "line 2: expected 'COMPUTED REFERENCE NAME', got '1.0 p0'");
  }
}
