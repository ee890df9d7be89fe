#pragma once
// AFFICHAGE of STAT_NON_LINE: where the convergence tables go. The Newton driver writes each
// step's table to this stream, which passes it on to the message file for the steps AFFICHAGE/PAS
// selects (every PAS-th step from the first: steps 1, 1 + PAS, 1 + 2 PAS...; every step by
// default) and, with AFFICHAGE/UNITE, to that unit's file as well (every step, the same layout).
// INFO_RESIDU='OUI' asks for the place of the largest residual: the WHERE (MAXI) column that
// every table has.

#include "interpreter/Diagnostics.hpp"

#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <streambuf>

namespace stella {

class Session;

// AFFICHAGE of STAT_NON_LINE: a table every `every` steps (PAS), on unit `unit` (UNITE, at
// `unitAt`) besides the message file.
struct ConvergenceDisplay {
  int every = 1;
  std::optional<int> unit;
  SourceLocation unitAt;
};

class ConvergenceTableOutput : public std::ostream {
public:
  // The unit file of `display` is opened (appended to) here.
  ConvergenceTableOutput(const ConvergenceDisplay& display, Session& session);

  // The table of step `number` (from 1) follows.
  void beginStep(int number);

  int every() const { return every_; }

private:
  class Buffer : public std::streambuf {
  public:
    std::ostream* message = nullptr;
    std::ostream* unit = nullptr;
    bool shown = true;

  protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
  };
  Buffer buffer_;
  std::unique_ptr<std::ofstream> unitFile_;
  int every_ = 1;
};

} // namespace stella
