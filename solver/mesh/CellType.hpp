#pragma once
// The cell types code_aster uses in solid mechanics, with code_aster's names (TRIA3, HEXA20...).
// Reference node orderings, faces and edges are in CellTopology.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace stella {

enum class CellType : std::uint8_t {
  POI1,
  SEG2,
  SEG3,
  TRIA3,
  TRIA6,
  TRIA7,
  QUAD4,
  QUAD8,
  QUAD9,
  TETRA4,
  TETRA10,
  PENTA6,
  PENTA15,
  PENTA18,
  PYRAM5,
  PYRAM13,
  HEXA8,
  HEXA20,
  HEXA27,
  SEG4,
};

inline constexpr int cellTypeCount = 20;

struct CellTypeInfo {
  CellType type;
  std::string_view name; // code_aster's name
  int nodeCount;
  int dimension;  // topological dimension: 0 point, 1 edge, 2 face, 3 volume
  bool quadratic; // has mid-edge nodes
};

inline constexpr std::array<CellTypeInfo, cellTypeCount> cellTypeTable{{
    {CellType::POI1, "POI1", 1, 0, false},       {CellType::SEG2, "SEG2", 2, 1, false},
    {CellType::SEG3, "SEG3", 3, 1, true},        {CellType::TRIA3, "TRIA3", 3, 2, false},
    {CellType::TRIA6, "TRIA6", 6, 2, true},      {CellType::TRIA7, "TRIA7", 7, 2, true},
    {CellType::QUAD4, "QUAD4", 4, 2, false},     {CellType::QUAD8, "QUAD8", 8, 2, true},
    {CellType::QUAD9, "QUAD9", 9, 2, true},      {CellType::TETRA4, "TETRA4", 4, 3, false},
    {CellType::TETRA10, "TETRA10", 10, 3, true}, {CellType::PENTA6, "PENTA6", 6, 3, false},
    {CellType::PENTA15, "PENTA15", 15, 3, true}, {CellType::PENTA18, "PENTA18", 18, 3, true},
    {CellType::PYRAM5, "PYRAM5", 5, 3, false},   {CellType::PYRAM13, "PYRAM13", 13, 3, true},
    {CellType::HEXA8, "HEXA8", 8, 3, false},     {CellType::HEXA20, "HEXA20", 20, 3, true},
    {CellType::HEXA27, "HEXA27", 27, 3, true},   {CellType::SEG4, "SEG4", 4, 1, true},
}};

constexpr const CellTypeInfo& info(CellType t) {
  return cellTypeTable[static_cast<std::size_t>(t)];
}
constexpr int nodeCount(CellType t) {
  return info(t).nodeCount;
}
constexpr int dimension(CellType t) {
  return info(t).dimension;
}
constexpr std::string_view name(CellType t) {
  return info(t).name;
}

inline std::optional<CellType> cellTypeFromName(std::string_view n) {
  for (const auto& i : cellTypeTable) {
    if (i.name == n) {
      return i.type;
    }
  }
  return std::nullopt;
}

} // namespace stella
