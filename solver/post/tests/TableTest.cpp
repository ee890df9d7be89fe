// IMPR_TABLE's three layouts of a table: TABLEAU (aligned columns), ASTER (#DEBUT_TABLE, the type
// line, #FIN_TABLE) and CSV (SEPARATEUR=','), with FORMAT_R and empty cells.

#include "solver/post/Table.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

Table sample() {
  Table t;
  t.addRow(
      {{"NOEUD", Value(std::string("N1"))}, {"INST", Value(0.5)}, {"NUME_ORDRE", Value(std::int64_t{1})}});
  t.addRow({{"NOEUD", Value(std::string("N12345678X"))}, {"INST", Value(1.0)}});
  return t;
}

TEST(TableFormat, Tableau) {
  const std::string text = sample().format("TABLEAU", " ", "E12.5");
  EXPECT_EQ(text, " NOEUD            INST             NUME_ORDRE\n"
                  " N1                5.00000E-01     1\n"
                  " N12345678X        1.00000E+00     -\n");
}

TEST(TableFormat, AsterHasMarkersAndTypes) {
  Table t = sample();
  t.title = "DEPLACEMENTS";
  const std::string text = t.format("ASTER", " ", "E12.5");
  EXPECT_EQ(text, "#DEBUT_TABLE\n"
                  "#TITRE DEPLACEMENTS\n"
                  " NOEUD            INST             NUME_ORDRE\n"
                  " K16              R                I\n"
                  " N1                5.00000E-01     1\n"
                  " N12345678X        1.00000E+00     -\n"
                  "#FIN_TABLE\n");
}

TEST(TableFormat, CsvWithFormatR) {
  const std::string text = sample().format("CSV", ",", "F8.3");
  EXPECT_EQ(text, "NOEUD,INST,NUME_ORDRE\nN1,0.500,1\nN12345678X,1.000,-\n");
}

} // namespace
} // namespace stella
