#pragma once
/// \file vtkCMPFileChecks.h
/// \brief What the readers share to keep a hostile file away from VTK 9.2's
///        own parsers (issue 26): the core's VTP check with VTK's
///        decompressors, a check of the cells VTK's XML reader made, a
///        collector of a VTK object's error messages, and the VTK arrays of
///        a file the core read. Not wrapped.

#include <cmp/io/MeshFile.h>
#include <cmp/mesh/Status.h>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>

#include <functional>
#include <string>
#include <vector>

class vtkPointData;
class vtkPolyData;

namespace cmp
{
namespace bridge
{

/// \brief Collects the error messages a VTK object emits instead of letting
///        them reach the output window (the first one is kept), while it
///        lives. \pre `watched` outlives it.
class ErrorCollector
{
public:
  explicit ErrorCollector(vtkObject* watched);
  ~ErrorCollector();
  ErrorCollector(const ErrorCollector&) = delete;
  ErrorCollector& operator=(const ErrorCollector&) = delete;
  const std::string& message() const { return message_; }
  /// \brief The last line of the message (VTK's own text, without the
  ///        "ERROR: In file, line" and object lines before it).
  std::string lastLine() const;

private:
  std::string message_;
  vtkNew<vtkCallbackCommand> callback_;
  vtkObject* watched_;
  unsigned long tag_;
};

/// \brief Refuses a file: empties `output` (if any), reports `message`
///        with `vtkErrorWithObjectMacro` on `reader`, and returns 0, what
///        the reader's `RequestData` then returns.
int refuse(vtkObject* reader, vtkPolyData* output, const std::string& message);

/// \brief Runs `read` (a VTK reader's own reading, on `reader`) and
///        returns what it said as one line naming `path`: its last error
///        message, made valid text (`Status`), or, if it failed silently,
///        that it failed; empty if it read without error. `result` gets what
///        `read` returned. VTK's readers do not name the file in their
///        messages and may quote damaged bytes.
std::string readWithMessages(vtkObject* reader, const std::string& path, const std::function<int()>& read, int& result);

/// \brief Copies to each point of `output` the point data of the first file
///        point that became it (`fileToMeshPoint`, as welding left it).
void copyWeldedPointData(vtkPointData* source, const std::vector<int>& fileToMeshPoint, vtkPolyData* output);

/// \brief The PLY attributes VTK 9.2's PLY reader kept, with its names and
///        types: point `Normals` (nx ny nz), point colours `RGB` or `RGBA`
///        (red green blue [alpha], or diffuse_red ...), point `TCoords` (u v
///        or texture_u texture_v), and face colours `RGB` on every triangle
///        of the face; from `data` (the core's PLY reading) onto `surface`.
void addPLYAttributes(const MeshFileData& data, vtkPolyData* surface);

/// \brief `checkVTPFile()` with VTK's own zlib, LZ4 and LZMA decompressors,
///        so compressed arrays are checked too. The message names the file
///        and the line.
Status checkVTPFileWithVTK(const std::string& path);

/// \brief Fails, naming `path`, if a cell of `data` (vertices, lines,
///        polygons or strips) has malformed offsets or a point id outside
///        the points; VTK's XML reader passes such ids on unchecked and
///        whatever draws or filters the cells reads out of bounds.
Status checkCellPointIds(vtkPolyData* data, const std::string& path);

} // namespace bridge
} // namespace cmp
