#pragma once
// MESURE of STAT_NON_LINE: the time measures of each step, as code_aster's table 'STAT' (one
// row per converged step): INST, Time_Time_Step (the wall time of the step, its failed attempts
// included, its storage not), Count_Newt_Iter, Time_Integrate (behaviour integration and
// assembly of forces and matrices), Time_Factor and Count_Factor (factorisations, their symbolic
// analysis included), Time_Solve, Count_LineSearch and Time_Other (the rest of the step: contact,
// residual algebra), so that Time_Integrate + Time_Factor + Time_Solve + Time_Other =
// Time_Time_Step. TABLE='OUI' attaches the table to the result (RECU_TABLE(CO=...,
// NOM_TABLE='STAT')); UNITE writes it to that unit at the end of the command.

#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/database/Result.hpp"
#include "solver/post/Table.hpp"

#include <chrono>
#include <memory>
#include <optional>

namespace stella {

class Session;

class StepMeasures {
public:
  StepMeasures() = default;
  // MESURE given: TABLE='OUI' (`keepTable`), UNITE (`unit`, at `unitAt`).
  StepMeasures(bool keepTable, std::optional<int> unit, const SourceLocation& unitAt);
  bool wanted() const { return keepTable_ || unit_.has_value(); }

  // Starts the clocks of the next step.
  void startStep(const MechanicalSystem& system);
  // The row of the step just converged at `time`.
  void endStep(const MechanicalSystem& system, double time, int iterations, int lineSearchIterations);

  // TABLE='OUI': the table goes to the result as 'STAT' (replacing that of an earlier run).
  void attach(Result& result) const;
  // UNITE: the table written to that unit (IMPR_TABLE's TABLEAU layout).
  void write(Session& session) const;

private:
  struct Snapshot {
    std::chrono::steady_clock::time_point wall;
    double integrate = 0.0;
    double factor = 0.0;
    double solve = 0.0;
    int factorizations = 0;
  };
  static Snapshot take(const MechanicalSystem& system);

  bool keepTable_ = false;
  std::optional<int> unit_;
  SourceLocation unitAt_;
  Snapshot start_;
  std::shared_ptr<Table> table_ = std::make_shared<Table>();
};

} // namespace stella
