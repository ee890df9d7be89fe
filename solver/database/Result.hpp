#pragma once
// A result concept (evol_elas, evol_noli): a sequence of stored steps, each with its storage
// number (NUME_ORDRE: STAT_NON_LINE stores its initial state as 0, MECA_STATIQUE starts at 1,
// as in code_aster), its time (INST) and fields by name (DEPL, SIEF_ELGA, VARI_ELGA, CONT_NOEU,
// REAC_NODA...). Commands that extend a result (reuse=) add steps or fields.
// Shared contract (written first by the lead): extend it, do not replace it.

#include "Field.hpp"
#include "interpreter/Value.hpp"
#include "solver/mesh/Mesh.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stella {

struct ResultStep {
  int number = 0;    // NUME_ORDRE
  double time = 0.0; // INST
  std::map<std::string, std::shared_ptr<Field>> fields;
  std::map<std::string, double> parameters; // e.g. ITER_GLOB, CHAR_MINI...

  const Field* field(const std::string& name) const;
};

class Result : public ConceptData {
public:
  std::string type; // evol_elas, evol_noli
  std::shared_ptr<const Mesh> mesh;
  std::shared_ptr<ConceptData> model;    // the modele concept's data
  std::shared_ptr<ConceptData> material; // the cham_mater concept's data

  std::vector<ResultStep> steps;
  // Tables a command attached to the result, by NOM_TABLE (STAT_NON_LINE: 'OBSERVATION',
  // 'STAT'), read back with RECU_TABLE. Table concepts (solver/post/Table.hpp).
  std::map<std::string, std::shared_ptr<ConceptData>> tables;

  // Adds a step after the last one (number = last + 1, or `first` for the first).
  ResultStep& addStep(double time, int first = 0);
  // The step stored at `time` within `precision` (relative unless `absolute`), or null.
  const ResultStep* stepAtTime(double time, double precision = 1.0e-6, bool absolute = false) const;
  const ResultStep* stepNumber(int number) const;
  ResultStep* stepNumber(int number);
  // Names of the fields stored in at least one step.
  std::vector<std::string> fieldNames() const;
};

} // namespace stella
