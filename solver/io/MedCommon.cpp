// MED types, orderings and file handle (see MedCommon.hpp).

#include "solver/io/MedCommon.hpp"

#include "solver/io/MeshFileError.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdio>

#include <algorithm>
#include <array>
#include <mutex>
#include <utility>

namespace stella {

namespace {

constexpr std::array<std::pair<CellType, med_geometry_type>, 20> medTypes{{
    {CellType::POI1, MED_POINT1},    {CellType::SEG2, MED_SEG2},       {CellType::SEG3, MED_SEG3},
    {CellType::SEG4, MED_SEG4},      {CellType::TRIA3, MED_TRIA3},     {CellType::QUAD4, MED_QUAD4},
    {CellType::TRIA6, MED_TRIA6},    {CellType::TRIA7, MED_TRIA7},     {CellType::QUAD8, MED_QUAD8},
    {CellType::QUAD9, MED_QUAD9},    {CellType::TETRA4, MED_TETRA4},   {CellType::PYRAM5, MED_PYRA5},
    {CellType::PENTA6, MED_PENTA6},  {CellType::HEXA8, MED_HEXA8},     {CellType::TETRA10, MED_TETRA10},
    {CellType::PYRAM13, MED_PYRA13}, {CellType::PENTA15, MED_PENTA15}, {CellType::PENTA18, MED_PENTA18},
    {CellType::HEXA20, MED_HEXA20},  {CellType::HEXA27, MED_HEXA27},
}};

// code_aster's numnoa tables (1-based there): aster node j is MED node perm[j].
constexpr std::array<int, 27> identity{0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13,
                                       14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
constexpr std::array<int, 10> tetra{0, 2, 1, 3, 6, 5, 4, 7, 9, 8};
constexpr std::array<int, 18> penta{0, 2, 1, 3, 5, 4, 8, 7, 6, 12, 14, 13, 11, 10, 9, 17, 16, 15};
constexpr std::array<int, 13> pyram{0, 3, 2, 1, 4, 8, 7, 6, 5, 9, 12, 11, 10};
constexpr std::array<int, 27> hexa{0,  3,  2,  1,  4,  7,  6,  5,  11, 10, 9,  8,  16, 19,
                                   18, 17, 15, 14, 13, 12, 20, 24, 23, 22, 21, 25, 26};

} // namespace

med_geometry_type medGeometryOf(CellType t) {
  for (const auto& [c, g] : medTypes) {
    if (c == t) {
      return g;
    }
  }
  return MED_NONE;
}

std::optional<CellType> cellTypeFromMed(med_geometry_type g) {
  for (const auto& [c, m] : medTypes) {
    if (m == g) {
      return c;
    }
  }
  return std::nullopt;
}

std::span<const int> medPermutation(CellType t) {
  const auto n = static_cast<std::size_t>(nodeCount(t));
  switch (t) {
  case CellType::TETRA4:
  case CellType::TETRA10:
    return {tetra.data(), n};
  case CellType::PENTA6:
  case CellType::PENTA15:
  case CellType::PENTA18:
    return {penta.data(), n};
  case CellType::PYRAM5:
  case CellType::PYRAM13:
    return {pyram.data(), n};
  case CellType::HEXA8:
  case CellType::HEXA20:
  case CellType::HEXA27:
    return {hexa.data(), n};
  default:
    return {identity.data(), n};
  }
}

const std::vector<CellType>& medCellOrder() {
  static const std::vector<CellType> order = [] {
    std::vector<std::pair<med_geometry_type, CellType>> v;
    for (const auto& [c, g] : medTypes) {
      v.emplace_back(g, c);
    }
    std::sort(v.begin(), v.end());
    std::vector<CellType> out;
    for (const auto& p : v) {
      out.push_back(p.second);
    }
    return out;
  }();
  return order;
}

StderrSilencer::StderrSilencer() {
  std::fflush(stderr);
  saved_ = ::dup(2);
  const int null = ::open("/dev/null", O_WRONLY);
  if (saved_ >= 0 && null >= 0) {
    ::dup2(null, 2);
  }
  if (null >= 0) {
    ::close(null);
  }
}

StderrSilencer::~StderrSilencer() {
  std::fflush(stderr);
  if (saved_ >= 0) {
    ::dup2(saved_, 2);
    ::close(saved_);
  }
}

void silenceHdf5Errors() {
  static std::once_flag once;
  std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

MedFile::MedFile(const std::filesystem::path& file, Mode mode, std::array<int, 3> version) : path_(file) {
  silenceHdf5Errors();
  const std::string p = file.string();
  std::error_code ec;
  if (mode == Mode::Read || mode == Mode::Append) {
    if (!std::filesystem::is_regular_file(file, ec)) {
      if (mode == Mode::Read) {
        throwFileError("MESHFILE_1", file, "the file does not exist or is not a regular file");
      }
      mode = Mode::Create;
    }
  }
  if (mode == Mode::Read) {
    if (std::filesystem::file_size(file, ec) == 0) {
      throwFileError("MESHFILE_1", file, "the file is empty");
    }
    med_bool hdfok = MED_FALSE;
    med_bool medok = MED_FALSE;
    if (MEDfileCompatibility(p.c_str(), &hdfok, &medok) < 0 || hdfok != MED_TRUE) {
      throwFileError("MESHFILE_4", file, "not an HDF5 file, so not a MED file (damaged or wrong FORMAT?)");
    }
    if (medok != MED_TRUE) {
      throwFileError("MESHFILE_4", file, "an HDF5 file but not a MED file this library can read");
    }
  }
  const med_access_mode access = mode == Mode::Read     ? MED_ACC_RDONLY
                                 : mode == Mode::Create ? MED_ACC_CREAT
                                                        : MED_ACC_RDWR;
  fid_ = mode == Mode::Create && version[0] > 0
             ? MEDfileVersionOpen(p.c_str(), access, version[0], version[1], version[2])
             : MEDfileOpen(p.c_str(), access);
  if (fid_ < 0) {
    throwFileError(mode == Mode::Read ? "MESHFILE_4" : "MESHFILE_7", file,
                   mode == Mode::Read ? "the MED library cannot open the file"
                                      : "the file cannot be created");
  }
  if (mode == Mode::Append && version[0] > 0) {
    med_int major = 0;
    med_int minor = 0;
    med_int release = 0;
    check(MEDfileNumVersionRd(fid_, &major, &minor, &release), "MEDfileNumVersionRd", "append");
    if (major != version[0] || minor != version[1]) {
      MEDfileClose(fid_);
      fid_ = -1;
      throwFileError("MESHFILE_7", file,
                     fmt::format("the file is in MED {}.{}, VERSION_MED asks {}.{}.{}: one file holds one "
                                 "version (write to another unit, or give the same VERSION_MED)",
                                 major, minor, version[0], version[1], version[2]));
    }
  }
}

MedFile::~MedFile() {
  if (fid_ >= 0) {
    MEDfileClose(fid_);
  }
}

void MedFile::check(med_err status, const char* call, const std::string& context) const {
  if (status < 0) {
    throwFileError("MESHFILE_4", path_, std::string(call) + " failed (" + context + "): damaged file?");
  }
}

std::string medName(const char* field, std::size_t width) {
  std::string s(field, width);
  const auto nul = s.find('\0');
  if (nul != std::string::npos) {
    s.resize(nul);
  }
  while (!s.empty() && s.back() == ' ') {
    s.pop_back();
  }
  return s;
}

std::string medPadded(const std::string& name, std::size_t width) {
  std::string s = name.substr(0, width);
  s.resize(width, ' ');
  return s;
}

} // namespace stella
