#pragma once
// A table concept (table_sdaster): named columns of reals, integers or texts, rows possibly
// with empty cells. Made by CREA_TABLE and POST_RELEVE_T, read by TEST_TABLE, printed by
// IMPR_TABLE.

#include "interpreter/Value.hpp"

#include <optional>
#include <string>
#include <vector>

namespace stella {

class Table : public ConceptData {
public:
  struct Column {
    std::string name;
    ValueList cells; // None for an empty cell; otherwise int, real or text
  };

  std::string title;

  // Adds a row; columns it names that do not exist yet are added (empty in earlier rows).
  void addRow(const std::vector<std::pair<std::string, Value>>& cells);
  // Appends a whole column (shorter columns are padded with empty cells).
  void addColumn(const std::string& name, ValueList cells);

  std::size_t rowCount() const { return rows_; }
  const std::vector<Column>& columns() const { return columns_; }
  const Column* column(const std::string& name) const;
  std::vector<std::string> columnNames() const;

  // IMPR_TABLE: FORMAT='TABLEAU' (aligned columns), 'ASTER' (between #DEBUT_TABLE and
  // #FIN_TABLE, with a line of column types R, I, K8, K16, K24 or K80 under the names, as
  // code_aster writes tables it can read back), 'CSV' (the names then the values, separated by
  // `separator`, no padding: IMPR_TABLE FORMAT='TABLEAU' with SEPARATEUR=','). Reals are
  // written with FORMAT_R, a Fortran edit descriptor Ew.d, Fw.d or Gw.d (default E12.5).
  std::string format(const std::string& kind, const std::string& separator = ",",
                     const std::string& realFormat = "E12.5") const;
  // The type code_aster gives a column: R, I, or K8 / K16 / K24 / K80 by the longest text.
  std::string columnType(const Column& column) const;

private:
  Column& ensureColumn(const std::string& name);
  std::vector<Column> columns_;
  std::size_t rows_ = 0;
};

} // namespace stella
