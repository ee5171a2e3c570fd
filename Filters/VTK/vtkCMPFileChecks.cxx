#include "vtkCMPFileChecks.h"

#include <cmp/io/VTPCheck.h>
#include "vtkCMPArrayNames.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <type_traits>

namespace cmp
{
namespace bridge
{

ErrorCollector::ErrorCollector(vtkObject* watched)
  : watched_(watched)
{
  callback_->SetClientData(&message_);
  callback_->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void* callData)
    {
      auto* message = static_cast<std::string*>(clientData);
      if (message->empty() && callData)
        *message = static_cast<const char*>(callData);
    });
  tag_ = watched->AddObserver(vtkCommand::ErrorEvent, callback_);
}

ErrorCollector::~ErrorCollector()
{
  watched_->RemoveObserver(tag_);
}

std::string ErrorCollector::lastLine() const
{
  std::string line = message_;
  line.erase(line.find_last_not_of(" \t\r\n") + 1);
  const std::size_t newline = line.find_last_of('\n');
  line = newline == std::string::npos ? line : line.substr(newline + 1);
  // "vtkClassName (0x...): text": keep the text.
  const std::size_t colon = line.find("): ");
  if (line.rfind("vtk", 0) == 0 && colon != std::string::npos)
    line = line.substr(colon + 3);
  return line;
}

namespace
{

/// One block of a compressed VTP array, decompressed by the compressor VTK's
/// reader would use.
bool decompressWithVTK(const std::string& compressor, const unsigned char* compressed, std::size_t compressedSize,
  unsigned char* raw, std::size_t rawSize)
{
  vtkSmartPointer<vtkDataCompressor> decompressor;
  if (compressor == "vtkZLibDataCompressor")
    decompressor = vtkSmartPointer<vtkZLibDataCompressor>::New();
  else if (compressor == "vtkLZ4DataCompressor")
    decompressor = vtkSmartPointer<vtkLZ4DataCompressor>::New();
  else if (compressor == "vtkLZMADataCompressor")
    decompressor = vtkSmartPointer<vtkLZMADataCompressor>::New();
  else
    return false;
  ErrorCollector quiet(decompressor); // a damaged block is checkVTPFile's to report
  return rawSize == 0 || decompressor->Uncompress(compressed, compressedSize, raw, rawSize) == rawSize;
}

} // namespace

int refuse(vtkObject* reader, vtkPolyData* output, const std::string& message)
{
  if (output)
    output->Initialize();
  vtkErrorWithObjectMacro(reader, << message);
  return 0;
}

std::string readWithMessages(vtkObject* reader, const std::string& path, const std::function<int()>& read, int& result)
{
  std::string said;
  {
    ErrorCollector errors(reader);
    result = read();
    said = errors.message().empty() ? std::string() : errors.lastLine();
  }
  if (said.empty() && result)
    return {};
  return Status::error("'" + path + "': " + (said.empty() ? std::string("the reader failed") : said)).message();
}

namespace
{

/// The values of the property named one of `names` (nullptr if none).
const std::vector<double>* propertyValues(
  const std::vector<cmp::MeshFileProperty>& properties, std::initializer_list<const char*> names)
{
  for (const char* name : names)
  {
    for (const cmp::MeshFileProperty& property : properties)
    {
      if (property.name == name)
        return &property.values;
    }
  }
  return nullptr;
}

/// A colour channel as VTK's PLY reader stores it: an unsigned char (a
/// value out of range is clamped, NaN is 0).
unsigned char colorChannel(double value)
{
  return std::isnan(value) ? 0 : static_cast<unsigned char>(std::clamp(value, 0.0, 255.0));
}

/// An array of the named properties, one component each (nullptr unless
/// every component is there).
template <class ArrayType>
vtkSmartPointer<ArrayType> propertyArray(const std::vector<cmp::MeshFileProperty>& properties, const char* arrayName,
  std::initializer_list<std::initializer_list<const char*>> components)
{
  std::vector<const std::vector<double>*> columns;
  for (const auto& names : components)
  {
    columns.push_back(propertyValues(properties, names));
    if (!columns.back())
      return nullptr;
  }
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(arrayName);
  array->SetNumberOfComponents(static_cast<int>(columns.size()));
  array->SetNumberOfTuples(static_cast<vtkIdType>(columns[0]->size()));
  for (std::size_t c = 0; c < columns.size(); ++c)
  {
    for (std::size_t i = 0; i < columns[c]->size(); ++i)
    {
      const double value = (*columns[c])[i];
      if constexpr (std::is_same_v<ArrayType, vtkUnsignedCharArray>)
        array->SetTypedComponent(static_cast<vtkIdType>(i), static_cast<int>(c), colorChannel(value));
      else
        array->SetTypedComponent(static_cast<vtkIdType>(i), static_cast<int>(c), static_cast<float>(value));
    }
  }
  return array;
}

} // namespace

/// Copies the point data of the first file point that became each surface point.
void copyWeldedPointData(vtkPointData* source, const std::vector<int>& fileToMeshPoint, vtkPolyData* output)
{
  const vtkIdType count = output->GetNumberOfPoints();
  std::vector<vtkIdType> firstFilePoint(count, -1);
  for (std::size_t i = 0; i < fileToMeshPoint.size(); ++i)
    if (firstFilePoint[fileToMeshPoint[i]] < 0)
      firstFilePoint[fileToMeshPoint[i]] = static_cast<vtkIdType>(i);
  vtkPointData* target = output->GetPointData();
  target->CopyAllocate(source, count);
  for (vtkIdType p = 0; p < count; ++p)
    target->CopyData(source, firstFilePoint[p], p);
}

/// The PLY attributes VTK 9.2's PLY reader kept, with its names and types:
/// point `Normals` (nx ny nz), point colours `RGB` or `RGBA` (red green blue
/// [alpha], or diffuse_red ...), point `TCoords` (u v or texture_u
/// texture_v), and face colours `RGB` on every triangle of the face.
void addPLYAttributes(const cmp::MeshFileData& data, vtkPolyData* surface)
{
  vtkNew<vtkPointData> filePoints;
  const auto& points = data.pointProperties;
  if (auto normals = propertyArray<vtkFloatArray>(points, cmp::bridge::kNormalsArray, { { "nx" }, { "ny" }, { "nz" } }))
    filePoints->SetNormals(normals);
  auto colors = propertyArray<vtkUnsignedCharArray>(points, cmp::bridge::kRGBAArray,
    { { "red", "diffuse_red" }, { "green", "diffuse_green" }, { "blue", "diffuse_blue" }, { "alpha" } });
  if (!colors)
    colors = propertyArray<vtkUnsignedCharArray>(points, cmp::bridge::kRGBArray,
      { { "red", "diffuse_red" }, { "green", "diffuse_green" }, { "blue", "diffuse_blue" } });
  if (colors)
    filePoints->SetScalars(colors);
  auto tcoords = propertyArray<vtkFloatArray>(points, cmp::bridge::kTCoordsArray, { { "u" }, { "v" } });
  if (!tcoords)
    tcoords = propertyArray<vtkFloatArray>(points, cmp::bridge::kTCoordsArray, { { "texture_u" }, { "texture_v" } });
  if (tcoords)
    filePoints->SetTCoords(tcoords);
  if (filePoints->GetNumberOfArrays() > 0)
    copyWeldedPointData(filePoints, data.fileToMeshPoint, surface);
  if (auto faceColors = propertyArray<vtkUnsignedCharArray>(
        data.triangleProperties, cmp::bridge::kRGBArray, { { "red" }, { "green" }, { "blue" } }))
    surface->GetCellData()->SetScalars(faceColors);
}


Status checkVTPFileWithVTK(const std::string& path)
{
  return checkVTPFile(path, decompressWithVTK);
}

Status checkCellPointIds(vtkPolyData* data, const std::string& path)
{
  const vtkIdType points = data->GetNumberOfPoints();
  const struct
  {
    vtkCellArray* cells;
    const char* name;
  } kinds[] = { { data->GetVerts(), "vertex" }, { data->GetLines(), "line" }, { data->GetPolys(), "polygon" },
    { data->GetStrips(), "strip" } };
  for (const auto& kind : kinds)
  {
    if (!kind.cells || kind.cells->GetNumberOfCells() == 0)
      continue;
    if (!kind.cells->IsValid())
      return Status::error("'" + path + "': the " + kind.name + " cells' offsets are malformed");
    vtkDataArray* ids = kind.cells->GetConnectivityArray();
    if (!ids || ids->GetNumberOfTuples() == 0)
      continue;
    double range[2];
    ids->GetRange(range, 0);
    if (range[0] < 0.0 || range[1] >= static_cast<double>(points))
      return Status::error("'" + path + "': a " + std::string(kind.name) + " cell uses point id " +
        std::to_string(static_cast<long long>(range[0] < 0.0 ? range[0] : range[1])) + ", but the file has " +
        std::to_string(static_cast<long long>(points)) + " points");
  }
  return {};
}

} // namespace bridge
} // namespace cmp
