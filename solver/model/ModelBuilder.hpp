#pragma once
// Assigning modelisations to cells (the work of AFFE_MODELE, usable without a command file).

#include "interpreter/SourceFile.hpp"
#include "solver/model/Model.hpp"

#include <span>
#include <string>

namespace stella {

// Assigns MODELISATION `name` ('3D', 'D_PLAN', 'C_PLAN', 'AXIS', 'DIS_T', '2D_DIS_T') to the
// cells that can carry it: volume elements on cells of the modelling's dimension, skin elements
// on cells one dimension lower, springs on POI1 cells. Throws UserError: MODEL_1 (modelisation
// not implemented yet), MODEL_2 (no cell of the selection can carry it), MODEL_3 (mixes 2D
// and 3D, or two volume modellings).
void assignModelling(Model& model, std::span<const CellId> cells, const std::string& name,
                     const SourceLocation& at);

// Final checks once every AFFE is done: MODEL_4 (2D model with z != 0), MODEL_5 (AXIS node at
// r < 0), MODEL_6 (no element at all).
void finishModel(Model& model, const SourceLocation& at);

} // namespace stella
