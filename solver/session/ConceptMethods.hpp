#pragma once
// Methods of concepts that command files call (`MAIL.getNumberOfNodes()`), as code_aster's
// Python objects offer them: one table per concept type, plus the methods every concept has.
// Session::conceptAttribute binds them to their concept.

#include "interpreter/Value.hpp"

#include <string>
#include <vector>

namespace stella {

// A method: the concept it is called on and the call's arguments. Throws UserError (located at
// the call by the evaluator) for wrong arguments.
using ConceptMethod = Value (*)(const Concept& object, const CallArguments& args);

// The method `name` of a concept of catalogue type `type`, or nullptr.
ConceptMethod findConceptMethod(const std::string& type, const std::string& name);
// The names of the methods a concept of type `type` has, sorted (for messages).
std::vector<std::string> conceptMethodNames(const std::string& type);

} // namespace stella
