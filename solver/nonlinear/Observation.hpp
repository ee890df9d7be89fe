#pragma once
// OBSERVATION of STAT_NON_LINE: at the instants each occurrence selects (every step by default;
// PAS_OBSE: every PAS_OBSE-th step; INST / LIST_INST with CRITERE and PRECISION; the initial
// state too with OBSE_ETAT_INIT='OUI', the default), the values FieldExtraction takes from the
// state become rows of the result's table 'OBSERVATION' (read back with RECU_TABLE(CO=...,
// NOM_TABLE='OBSERVATION')), with code_aster's columns: NOM_OBSERVATION (TITRE, else
// OBSERVATION_<occurrence>), TYPE_OBJET ('R'), NOM_SD (''), NUME_REUSE (0, then +1 at each
// reuse= continuation), NUME_OBSE (the row number), INST, NOM_CHAM, EVAL_CHAM, NOM_CMP, then
// NOEUD (nodal VALE) or MAILLE and POINT (Gauss-point VALE) or EVAL_ELGA, and VALE.

#include "solver/database/Result.hpp"
#include "solver/nonlinear/FieldExtraction.hpp"
#include "solver/post/Table.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace stella {

class Observations {
public:
  // One OBSERVATION occurrence.
  struct Item {
    FieldExtraction what;
    std::string title;
    bool initial = true;
    int every = 0;                // PAS_OBSE (0: not given)
    std::vector<double> instants; // INST / LIST_INST
    double precision = 1.0e-6;
    bool absolute = false;
    bool due(int index, double time) const;
  };
  Observations() = default;
  explicit Observations(std::vector<Item> items) : items_(std::move(items)) {}
  bool empty() const { return items_.empty(); }

  // The table the rows go to: the result's 'OBSERVATION' table, continued at a reuse=.
  void attach(Result& result);

  // Observes the state of step `index` (0: the initial state) at `time`; `field` gives a field
  // of the state by name (null when it has none).
  void observe(int index, double time, const std::function<const Field*(const std::string&)>& field,
               const Mesh& mesh);

private:
  // The columns of a new table, in code_aster's order (those the occurrences use).
  std::vector<std::string> columnNames() const;
  std::vector<Item> items_;
  std::shared_ptr<Table> table_;
  int reuse_ = 0;
};

} // namespace stella
