// MED types, orderings and file handle (see MedCommon.hpp).

#include "solver/io/MedCommon.hpp"

#include "solver/io/MeshFileError.hpp"
#include "solver/session/ExceptionDiagnostic.hpp"

#include <cerrno>

#include <dlfcn.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdio>

#include <algorithm>
#include <array>
#include <mutex>
#include <utility>
#include <vector>

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

namespace {

// The HDF5 library the MED library was linked with. Debian's libmedC uses the MPI build of
// HDF5 while stella links the serial one: both are in the process, and a file MED opened lives
// in MED's. Its functions are found through libmedC's dependencies.
void* medHdf5Symbol(const char* name) {
  static void* handle = [] {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&MEDfileOpen), &info) == 0 || info.dli_fname == nullptr) {
      return static_cast<void*>(nullptr);
    }
    return dlopen(info.dli_fname, RTLD_LAZY | RTLD_NOLOAD);
  }();
  return handle != nullptr ? dlsym(handle, name) : nullptr;
}

template <typename F> F* medHdf5(const char* name) {
  return reinterpret_cast<F*>(medHdf5Symbol(name));
}

// After a failed write or close (a full disk), HDF5 still holds the file and the objects MED
// opened in it; its exit handlers would then crash closing them (HDF5 1.10, H5F__close_cb).
// Every object MED opened in the file is closed here.
void forceClose(med_idt fid) {
  auto count = medHdf5<ssize_t(hid_t, unsigned)>("H5Fget_obj_count");
  auto list = medHdf5<ssize_t(hid_t, unsigned, size_t, hid_t*)>("H5Fget_obj_ids");
  auto type = medHdf5<H5I_type_t(hid_t)>("H5Iget_type");
  auto decRef = medHdf5<int(hid_t)>("H5Idec_ref");
  auto valid = medHdf5<htri_t(hid_t)>("H5Iis_valid");
  if (count == nullptr || list == nullptr || type == nullptr || decRef == nullptr || valid == nullptr) {
    return;
  }
  const ssize_t n = count(fid, H5F_OBJ_ALL | H5F_OBJ_LOCAL);
  if (n > 0) {
    std::vector<hid_t> ids(static_cast<std::size_t>(n));
    const ssize_t got = list(fid, H5F_OBJ_ALL | H5F_OBJ_LOCAL, ids.size(), ids.data());
    for (ssize_t i = 0; i < got; ++i) {
      const hid_t id = ids[static_cast<std::size_t>(i)];
      if (type(id) != H5I_FILE) {
        while (valid(id) > 0 && decRef(id) >= 0) {
        }
      }
    }
  }
  // The file itself is not closed again: HDF5 1.10 crashes closing a file whose flush failed.
  // It stays open, unflushed, until the process ends (no exit handler touches it, see
  // silenceHdf5Errors); its temporary name is removed by the writer.
  static_cast<void>(fid);
}

} // namespace

void silenceHdf5Errors() {
  static std::once_flag once;
  std::call_once(once, [] {
    // HDF5's exit handlers close the files still open, and crash on one whose write failed (a
    // full disk: HDF5 1.10, H5F__close_cb). stella closes every file itself (MedFile), so the
    // handlers are not installed; this must come before any other HDF5 call.
    if (auto dontAtExit = medHdf5<herr_t()>("H5dont_atexit")) {
      dontAtExit();
    }
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  });
}

MedFile::MedFile(const std::filesystem::path& file, Mode mode, std::filesystem::path shown,
                 std::array<int, 3> version)
    : path_(file), shown_(shown.empty() ? file : std::move(shown)), mode_(mode) {
  silenceHdf5Errors();
  const std::string p = file.string();
  std::error_code ec;
  if (mode == Mode::Read || mode == Mode::Append) {
    if (!std::filesystem::is_regular_file(file, ec)) {
      if (mode == Mode::Read) {
        throwFileError("MESHFILE_1", file, {});
      }
      mode = Mode::Create;
    }
  }
  if (mode == Mode::Read) {
    if (std::filesystem::file_size(file, ec) == 0) {
      throwFileError("MESHFILE_1.3", file, {});
    }
    med_bool hdfok = MED_FALSE;
    med_bool medok = MED_FALSE;
    if (MEDfileCompatibility(p.c_str(), &hdfok, &medok) < 0 || hdfok != MED_TRUE) {
      throwFileError("MESHFILE_4", file, {});
    }
    if (medok != MED_TRUE) {
      throwFileError("MESHFILE_4.2", file, {});
    }
  }
  const med_access_mode access = mode == Mode::Read     ? MED_ACC_RDONLY
                                 : mode == Mode::Create ? MED_ACC_CREAT
                                                        : MED_ACC_RDWR;
  errno = 0;
  fid_ = mode == Mode::Create && version[0] > 0
             ? MEDfileVersionOpen(p.c_str(), access, version[0], version[1], version[2])
             : MEDfileOpen(p.c_str(), access);
  if (fid_ < 0) {
    if (mode == Mode::Read) {
      throwFileError("MESHFILE_4.3", shown_, {});
    }
    mode_ = mode;
    check(-1, "MEDfileOpen", "creating the file");
  }
  if (mode == Mode::Append && version[0] > 0) {
    med_int major = 0;
    med_int minor = 0;
    med_int release = 0;
    check(MEDfileNumVersionRd(fid_, &major, &minor, &release), "MEDfileNumVersionRd", "append");
    if (major != version[0] || minor != version[1]) {
      MEDfileClose(fid_);
      fid_ = -1;
      throwFileError("MESHFILE_7.3", file,
                     {{"major", major},
                      {"minor", minor},
                      {"version", version[0]},
                      {"version_2", version[1]},
                      {"version_3", version[2]}});
    }
  }
}

MedFile::~MedFile() {
  if (fid_ >= 0 && MEDfileClose(fid_) < 0) {
    forceClose(fid_);
  }
}

void MedFile::close() {
  if (fid_ < 0) {
    return;
  }
  errno = 0;
  const med_err status = MEDfileClose(fid_);
  if (status < 0) {
    const int error = errno;
    forceClose(fid_);
    errno = error;
  }
  fid_ = -1;
  check(status, "MEDfileClose", "writing what the file still held");
}

void MedFile::check(med_err status, const char* call, const std::string& context) const {
  const int error = errno;
  if (status >= 0) {
    errno = 0; // a later failure reads only its own reason
    return;
  }
  if (mode_ == Mode::Read) {
    throwFileError("MESHFILE_4.4", shown_, {{"call", std::string(call)}, {"context", context}});
  }
  const bool osError = error == ENOSPC || error == EFBIG || error == EDQUOT || error == EIO ||
                       error == EROFS || error == EACCES || error == EPERM || error == ENOENT ||
                       error == ENOTDIR || error == EISDIR;
  throw UserError(
      msg::make(
          osError ? "MESHFILE_7.os" : "MESHFILE_7.med",
          {{"file", shown_.string()}, {"call", call}, {"context", context}, {"reason", osReason(error)}})
          .withNote(osError ? osAdvice(error) : msg::text("MESHFILE_7.n1")));
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
