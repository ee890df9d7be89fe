#pragma once
// The boundary between the command language and the rest of stella. The evaluator calls it for
// every command call; the session implements it (validate against the catalogue, echo, run the
// operator, time it), `stella check` implements it without running operators.

#include "Value.hpp"

#include <string>

namespace stella {

class CommandHandler {
public:
  virtual ~CommandHandler() = default;

  // A command call `CMD(...)`. `target` is the text of the assignment target when the call is
  // the whole right-hand side of an assignment (`MAIL` in `MAIL = LIRE_MAILLAGE(...)`,
  // `RES[1]` in `RES[i] = STAT_NON_LINE(...)` with i == 1), empty otherwise. Returns the
  // concept made (or None). Throws UserError for the user's mistakes.
  virtual Value callCommand(const std::string& command, const CallArguments& args,
                            const std::string& target) = 0;

  // `obj.NAME` where obj is a concept (e.g. `TAB.EXTR_TABLE`, `RES.LIST_PARA`). Throws
  // UserError when the concept has no such attribute.
  virtual Value conceptAttribute(const std::shared_ptr<Concept>& object, const std::string& name,
                                 const SourceLocation& at) = 0;

  // Called when FIN() has been executed; text after it is ignored.
  virtual bool finished() const = 0;
};

} // namespace stella
