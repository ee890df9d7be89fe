// ConvergenceTableOutput: AFFICHAGE (PAS, UNITE) applied to the convergence tables.

#include "solver/nonlinear/ConvergenceTableOutput.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

ConvergenceTableOutput::ConvergenceTableOutput(const ConvergenceDisplay& display, Session& session)
    : std::ostream(nullptr) {
  rdbuf(&buffer_);
  buffer_.message = &session.message();
  every_ = display.every;
  if (display.unit) {
    const int unit = *display.unit;
    if (unit == 6) {
      return; // the message file already has every table
    }
    if (unit == 8) {
      buffer_.unit = &session.result();
      return;
    }
    unitFile_ = std::make_unique<std::ofstream>(session.unitPath(unit, display.unitAt, false), std::ios::app);
    if (!*unitFile_) {
      throw UserError(msg::make("SNL_22", {{"unit", unit}}, display.unitAt));
    }
    buffer_.unit = unitFile_.get();
  }
}

void ConvergenceTableOutput::beginStep(int number) {
  buffer_.shown = every_ <= 1 || (number - 1) % every_ == 0;
}

ConvergenceTableOutput::Buffer::int_type ConvergenceTableOutput::Buffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) {
    return traits_type::not_eof(c);
  }
  const char ch = traits_type::to_char_type(c);
  xsputn(&ch, 1);
  return c;
}

std::streamsize ConvergenceTableOutput::Buffer::xsputn(const char* s, std::streamsize n) {
  if (shown) {
    message->write(s, n);
  }
  if (unit != nullptr) {
    unit->write(s, n);
  }
  return n;
}

} // namespace stella
