#pragma once
// The registry of operators: catalogue command name -> C++ function. One operator per file in
// solver/operators/, registered in one line with STELLA_OPERATOR("NAME", function). A name can
// be added, never replaced: a second registration of a name is an internal error at start-up.

#include "catalog/KeywordTree.hpp"
#include "interpreter/Value.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace stella {

class Session;
class TestReportSink;

// Everything an operator receives for one call.
struct OperatorCall {
  Session& session;
  const std::string& command;      // catalogue name, e.g. LIRE_MAILLAGE
  const KeywordTree& keywords;     // validated and complete
  const std::string& resultName;   // assignment target ("" when none)
  const std::string& resultType;   // catalogue result type ("" for a procedure)
  std::shared_ptr<Concept> reused; // reuse=X, if given
  SourceLocation location;         // of the command name in the command file

  // A new concept of the call's result type named after the assignment target (or the
  // reused concept, whose data is replaced).
  Value makeConcept(std::shared_ptr<ConceptData> data) const;
  // Where TEST_RESU and TEST_TABLE report their lines and OK/NOOK counts (the session's
  // result and message files), without the rest of the Session.
  TestReportSink& testReport() const;
};

using OperatorFunction = Value (*)(OperatorCall& call);

class OperatorRegistry {
public:
  static OperatorRegistry& instance();
  // Throws InternalError when `name` is already registered.
  bool add(const std::string& name, OperatorFunction fn, const char* file);
  OperatorFunction find(const std::string& name) const;
  std::vector<std::string> names() const;

private:
  std::map<std::string, std::pair<OperatorFunction, std::string>> operators_;
};

} // namespace stella

#define STELLA_OPERATOR_CONCAT2(a, b) a##b
#define STELLA_OPERATOR_CONCAT(a, b) STELLA_OPERATOR_CONCAT2(a, b)
#define STELLA_OPERATOR(NAME, FUNCTION)                                                                      \
  static const bool STELLA_OPERATOR_CONCAT(stellaOperatorRegistered_, __LINE__) =                            \
      ::stella::OperatorRegistry::instance().add(NAME, FUNCTION, __FILE__)
