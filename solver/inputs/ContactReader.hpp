#pragma once
// Reading the keyword tree of DEFI_CONTACT into the plain ContactDefinition the contact numerics
// receive (solver/contact/ContactDefinition.hpp), each keyword once, with its source location
// where a later check refers to it.

#include "solver/contact/ContactDefinition.hpp"

#include <memory>

namespace stella {

class KeywordTree;

namespace contact {

// Reads the keyword tree of DEFI_CONTACT (validated by the catalogue). `mesh` is the model's
// mesh. The checks against the mesh are checkContactDefinition's.
std::shared_ptr<ContactDefinition> readContactDefinition(const KeywordTree& keywords,
                                                         std::shared_ptr<const Mesh> mesh);

} // namespace contact
} // namespace stella
