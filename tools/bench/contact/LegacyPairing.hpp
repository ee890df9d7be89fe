#pragma once
// The pairing of stella before issue 23 (kd-tree of master nodes, cells around the 4 then 16
// nearest nodes), kept only so that the benchmark can time it beside the current one.

#include "solver/contact/ContactPairing.hpp"

namespace stella::contact::legacy {

std::vector<ContactLink> pairZone(const Mesh& mesh, const NodePosition& position, int zoneIndex,
                                  const ContactZone& zone, const PairingOptions& options);

} // namespace stella::contact::legacy
