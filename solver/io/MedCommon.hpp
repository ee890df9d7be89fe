#pragma once
// Shared pieces of the MED reader and writers: code_aster <-> MED cell types and node orderings
// (code_aster's lrmtyp: MED orients volumes the other way and orders some quadratic nodes
// differently), an RAII MED file handle that silences HDF5's error stack printing, and fixed-
// width MED name handling.

#include "solver/mesh/CellType.hpp"

// Debian's med.h declares MEDparFileOpen with MPI types (MED_HAVE_MPI) but stella uses the
// sequential API only: stand-in declarations keep the header compilable without mpi.h. Files
// that include this header must not include mpi.h.
#ifndef OMPI_MPI_H
using MPI_Comm = int;
using MPI_Info = int;
#endif
#include <med.h>

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stella {

med_geometry_type medGeometryOf(CellType t);
std::optional<CellType> cellTypeFromMed(med_geometry_type g);
// aster[j] = med[perm[j]] (0-based).
std::span<const int> medPermutation(CellType t);
// Every CellType MED supports, by increasing MED geometry number (the order cells are stored).
const std::vector<CellType>& medCellOrder();

// A MED file open for reading or writing; closed by the destructor. Opening failures raise
// MESHFILE_1 (missing) or MESHFILE_4 (not an HDF5/MED file) naming the file.
// `version` (IMPR_RESU VERSION_MED: major, minor, release; {0, 0, 0} = the library's own) is the
// MED format a created file is written in (the library records its own release number of that
// minor version); appending to a file of another major.minor raises MESHFILE_7.
class MedFile {
public:
  enum class Mode { Read, Create, Append };
  // `shown`: the path the messages give (a file written under a temporary name is named by its
  // final one); empty: `file`.
  MedFile(const std::filesystem::path& file, Mode mode, std::filesystem::path shown = {},
          std::array<int, 3> version = {0, 0, 0});
  // `version`: the MED version a created file is written in (MEDfileVersionOpen); {0, 0, 0}: the library's.
  ~MedFile();
  MedFile(const MedFile&) = delete;
  MedFile& operator=(const MedFile&) = delete;
  med_idt id() const { return fid_; }
  const std::filesystem::path& path() const { return path_; }
  // MESHFILE_4 "<call> failed (<context>)" when status < 0; for a file being written,
  // MESHFILE_7 with the OS reason (a full disk, the file-size limit...).
  void check(med_err status, const char* call, const std::string& context) const;
  // Closes the file, checked: HDF5 writes what it still holds here, so a full disk can show
  // only now. The destructor closes a file still open without a word (after an error).
  void close();

private:
  std::filesystem::path path_;
  std::filesystem::path shown_;
  Mode mode_;
  med_idt fid_ = -1;
};

// While alive, the process's standard error goes to /dev/null: the MED library prints its own
// diagnostics to stderr on failures; stella reports them as MESHFILE_4 instead.
class StderrSilencer {
public:
  StderrSilencer();
  ~StderrSilencer();
  StderrSilencer(const StderrSilencer&) = delete;
  StderrSilencer& operator=(const StderrSilencer&) = delete;

private:
  int saved_ = -1;
};

// Silences HDF5's automatic error printing (once per process).
void silenceHdf5Errors();

// A fixed-width MED name field (trailing blanks and NULs removed).
std::string medName(const char* field, std::size_t width);
// `name` padded with blanks to `width` characters (truncated when longer).
std::string medPadded(const std::string& name, std::size_t width);

} // namespace stella
