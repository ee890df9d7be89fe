// Gmsh element types and node orderings (Gmsh reference manual, "Node ordering") against
// code_aster's (CellTopology.hpp). Vertices agree for every type; quadratic nodes differ for
// TETRA10 (last two edges swapped), PENTA15/18, PYRAM13 and HEXA20/27 where Gmsh orders edges
// by their first vertex.

#include "solver/io/GmshCellTypes.hpp"

#include <array>
#include <utility>

namespace stella {

namespace {

constexpr std::array<std::pair<int, CellType>, 19> gmshTypes{{
    {15, CellType::POI1},    {1, CellType::SEG2},     {8, CellType::SEG3},     {26, CellType::SEG4},
    {2, CellType::TRIA3},    {9, CellType::TRIA6},    {3, CellType::QUAD4},    {16, CellType::QUAD8},
    {10, CellType::QUAD9},   {4, CellType::TETRA4},   {11, CellType::TETRA10}, {6, CellType::PENTA6},
    {18, CellType::PENTA15}, {13, CellType::PENTA18}, {7, CellType::PYRAM5},   {19, CellType::PYRAM13},
    {5, CellType::HEXA8},    {17, CellType::HEXA20},  {12, CellType::HEXA27},
}};

constexpr std::array<int, 27> identity{0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13,
                                       14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
constexpr std::array<int, 10> tetra10{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
constexpr std::array<int, 18> penta18{0, 1, 2, 3, 4, 5, 6, 9, 7, 8, 10, 11, 12, 14, 13, 15, 17, 16};
constexpr std::array<int, 13> pyram13{0, 1, 2, 3, 4, 5, 8, 10, 6, 7, 9, 11, 12};
constexpr std::array<int, 27> hexa27{0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  10, 12,
                                     14, 15, 16, 18, 19, 17, 20, 21, 23, 24, 22, 25, 26};

} // namespace

std::optional<CellType> cellTypeFromGmsh(int gmshType) {
  for (const auto& [g, t] : gmshTypes) {
    if (g == gmshType) {
      return t;
    }
  }
  return std::nullopt;
}

int gmshTypeOf(CellType t) {
  for (const auto& [g, c] : gmshTypes) {
    if (c == t) {
      return g;
    }
  }
  return 0;
}

std::span<const int> gmshPermutation(CellType t) {
  const auto n = static_cast<std::size_t>(nodeCount(t));
  switch (t) {
  case CellType::TETRA10:
    return {tetra10.data(), n};
  case CellType::PENTA15:
  case CellType::PENTA18:
    return {penta18.data(), n};
  case CellType::PYRAM13:
    return {pyram13.data(), n};
  case CellType::HEXA20:
  case CellType::HEXA27:
    return {hexa27.data(), n};
  default:
    return {identity.data(), n};
  }
}

} // namespace stella
