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

  // IMPR_TABLE: FORMAT='TABLEAU' (aligned columns), 'ASTER' (with #DEBUT_TABLE markers),
  // 'CSV' (separator `sep`).
  std::string format(const std::string& kind, const std::string& separator = ",") const;

private:
  Column& ensureColumn(const std::string& name);
  std::vector<Column> columns_;
  std::size_t rows_ = 0;
};

} // namespace stella
