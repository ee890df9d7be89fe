// TEST_TABLE: tests one value of a table (after FILTRE, or the MIN/MAX/SOMM/SOMM_ABS of a
// column) against VALE_CALC and a reference, printing OK/NOOK lines.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/TableFilter.hpp"
#include "solver/inputs/TestKeywords.hpp"
#include "solver/post/Table.hpp"
#include "solver/post/TestReport.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

Value runTestTable(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  auto tableConcept = kw.conceptValue("TABLE");
  auto table = conceptData<Table>(tableConcept);
  STELLA_ASSERT(table != nullptr, "TABLE holds no table");
  const std::string para = kw.text("NOM_PARA");
  const Table::Column* col = table->column(para);
  if (col == nullptr) {
    throw UserError(msg::make(
        "TABLE_1.4",
        {{"name", tableConcept->name}, {"para", para}, {"join", fmt::join(table->columnNames(), ", ")}},
        kw.locationOf("NOM_PARA")));
  }
  std::vector<std::size_t> rows = filterRows(*table, kw.occurrences("FILTRE"));
  std::vector<double> values;
  for (std::size_t r : rows) {
    if (col->cells[r].isNumber()) {
      values.push_back(col->cells[r].asReal());
    }
  }
  const std::string type = kw.textOr("TYPE_TEST", "");
  if (values.empty() || (type.empty() && values.size() != 1)) {
    throw UserError(msg::make("TABLE_3",
                              {{"values_count", values.size()}, {"para", para}, {"name", tableConcept->name}},
                              call.location)
                        .withNote(values.empty() ? msg::text("TABLE_3.n1") : msg::text("TABLE_3.n2")));
  }
  double computed = type.empty() ? values.front() : reduceByTestType(type, values);
  if (kw.text("VALE_ABS") == "OUI") {
    computed = std::fabs(computed);
  }
  std::vector<std::pair<std::string, std::string>> header{{"TABLE", tableConcept->name}, {"NOM_PARA", para}};
  if (!type.empty()) {
    header.emplace_back("TYPE_TEST", type);
  }
  for (const auto& f : kw.occurrences("FILTRE")) {
    std::string value =
        f.has("VALE") ? Value(f.real("VALE")).repr()
                      : (f.has("VALE_I") ? std::to_string(f.integer("VALE_I")) : f.textOr("VALE_K", ""));
    header.emplace_back(f.text("NOM_PARA"), f.text("CRIT_COMP") + " " + value);
  }
  reportTest(call.testReport(), header, valueTestFromKeywords(kw, computed, para));
  return Value();
}

} // namespace

STELLA_OPERATOR("TEST_TABLE", runTestTable);

} // namespace stella
