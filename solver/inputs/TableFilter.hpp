#pragma once
// Row selection of TEST_TABLE, POST_RELEVE_T... by FILTRE occurrences: NOM_PARA, CRIT_COMP
// (EQ, NE, LT, GT, LE, GE, VIDE, NON_VIDE, MAXI, MAXI_ABS, MINI, MINI_ABS), VALE / VALE_I /
// VALE_K, CRITERE and PRECISION for real equality.

#include "catalog/KeywordTree.hpp"
#include "solver/post/Table.hpp"

#include <vector>

namespace stella {

// The indices of the rows of `table` kept by every filter. Throws UserError (TABLE_1) naming
// the parameter when a filter names a column the table does not have.
std::vector<std::size_t> filterRows(const Table& table, const std::vector<KeywordTree>& filters);

} // namespace stella
