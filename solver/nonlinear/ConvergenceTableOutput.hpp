#pragma once
// AFFICHAGE of STAT_NON_LINE: where the convergence tables go. The Newton driver writes each
// step's table to this stream, which passes it on to the message file for the steps AFFICHAGE/PAS
// selects (every PAS-th step from the first: steps 1, 1 + PAS, 1 + 2 PAS...; every step by
// default) and, with AFFICHAGE/UNITE, to that unit's file as well (every step, the same layout).
// INFO_RESIDU='OUI' asks for the place of the largest residual: the WHERE (MAXI) column that
// every table has.

#include "catalog/KeywordTree.hpp"

#include <fstream>
#include <memory>
#include <ostream>
#include <streambuf>

namespace stella {

class Session;

class ConvergenceTableOutput : public std::ostream {
public:
  // Reads AFFICHAGE of STAT_NON_LINE; the unit file is opened (appended to) here.
  ConvergenceTableOutput(const KeywordTree& statNonLine, Session& session);

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
