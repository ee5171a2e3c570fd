#include "vtkCMPSurfaceReader.h"

#include <cmp/io/MeshFile.h>
#include <cmp/io/STLCheck.h>
#include <cmp/io/VTPCheck.h>
#include "vtkCMPPolyDataBridge.h"

#include <vtkAbstractPolyDataReader.h>
#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformationVector.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <type_traits>

vtkStandardNewMacro(vtkCMPSurfaceReader);

namespace
{

/// Collects the error messages a VTK reader emits instead of letting them
/// reach the output window, so they can be reported as ours.
class ErrorCollector
{
public:
  explicit ErrorCollector(vtkObject* watched)
  {
    callback_->SetClientData(&message_);
    callback_->SetCallback(
      [](vtkObject*, unsigned long, void* clientData, void* callData)
      {
        auto* message = static_cast<std::string*>(clientData);
        if (message->empty() && callData)
          *message = static_cast<const char*>(callData);
      });
    watched->AddObserver(vtkCommand::ErrorEvent, callback_);
  }
  const std::string& message() const { return message_; }

private:
  std::string message_;
  vtkNew<vtkCallbackCommand> callback_;
};

/// One block of a compressed VTP array, decompressed by the compressor VTK's
/// reader would use, for checkVTPFile's checks of compressed values.
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

/// Reads STL or VTP with VTK's readers and triangulates polygons.
cmp::Status readWithVTK(const std::string& path, const std::string& extension, vtkSmartPointer<vtkPolyData>& result)
{
  // VTK 9.2's readers trust the files' counts and types: check them first.
  if (extension == "stl")
  {
    if (cmp::Status s = cmp::checkSTLFile(path); !s.ok())
      return s;
  }
  else if (cmp::Status s = cmp::checkVTPFile(path, decompressWithVTK); !s.ok())
    return s; // names the file and the line
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == "stl")
  {
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(path.c_str());
    stl->MergingOff(); // welding is done exactly, below, for every format
    reader = stl;
  }
  else
  {
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName(path.c_str());
    reader = xml;
  }
  ErrorCollector errors(reader);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputConnection(reader->GetOutputPort());
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  ErrorCollector triangulateErrors(triangulate);
  triangulate->Update();
  result = triangulate->GetOutput();
  if (!errors.message().empty() || result->GetNumberOfPoints() == 0)
  {
    // VTK's message ends with the reader's own last line; keep only that.
    std::string detail = errors.message();
    detail.erase(detail.find_last_not_of(" \t\r\n") + 1);
    const std::size_t newline = detail.find_last_of('\n');
    detail = newline == std::string::npos ? detail : detail.substr(newline + 1);
    return cmp::Status::error("cannot read '" + path + "' as " + extension + (detail.empty() ? "" : ": " + detail));
  }
  return {};
}

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

void addTextureCoordinates(const cmp::MeshFileData& data, vtkPolyData* output)
{
  const auto& corners = data.cornerTexCoords;
  auto cornerArray = vtkSmartPointer<vtkFloatArray>::New();
  cornerArray->SetName(cmp::bridge::kCornerTCoordsArray);
  cornerArray->SetNumberOfComponents(6);
  cornerArray->SetNumberOfTuples(static_cast<vtkIdType>(corners.size()));
  // Point texture coordinates are only meaningful if no point sits on a seam.
  std::vector<Eigen::Vector2d> pointTex(data.mesh.vertexCount(), Eigen::Vector2d::Constant(NAN));
  bool seamless = true;
  for (std::size_t t = 0; t < corners.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      cornerArray->SetComponent(static_cast<vtkIdType>(t), 2 * k, corners[t][k].x());
      cornerArray->SetComponent(static_cast<vtkIdType>(t), 2 * k + 1, corners[t][k].y());
      Eigen::Vector2d& known = pointTex[data.mesh.triangles[t][k]];
      if (std::isnan(known.x()))
        known = corners[t][k];
      else if (known != corners[t][k])
        seamless = false;
    }
  }
  output->GetCellData()->AddArray(cornerArray);
  if (!seamless)
    return;
  auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
  tcoords->SetName(cmp::bridge::kTCoordsArray);
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(data.mesh.vertexCount());
  for (int v = 0; v < data.mesh.vertexCount(); ++v)
    tcoords->SetTuple2(v, pointTex[v].x(), pointTex[v].y());
  output->GetPointData()->SetTCoords(tcoords);
}

} // namespace

vtkCMPSurfaceReader::vtkCMPSurfaceReader()
{
  this->SetNumberOfInputPorts(0);
}

bool vtkCMPSurfaceReader::CanReadExtension(const char* fileName)
{
  const std::string ext = cmp::fileExtension(fileName ? fileName : "");
  return ext == "off" || ext == "obj" || ext == "ply" || ext == "stl" || ext == "vtp";
}

int vtkCMPSurfaceReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (this->FileName.empty())
  {
    vtkErrorMacro("no file name set");
    return 0;
  }
  if (!CanReadExtension(this->FileName.c_str()))
  {
    vtkErrorMacro("cannot read '" << this->FileName << "': unknown extension (use .off, .obj, .ply, .stl or .vtp)");
    return 0;
  }
  if (!std::filesystem::is_regular_file(this->FileName))
  {
    vtkErrorMacro("cannot open '" << this->FileName << "': no such file");
    return 0;
  }
  const std::string ext = cmp::fileExtension(this->FileName);
  cmp::MeshFileData data;
  vtkSmartPointer<vtkPolyData> fromVTK;
  cmp::Status status;
  if (ext == "off")
    status = cmp::readOFF(this->FileName, data);
  else if (ext == "obj")
    status = cmp::readOBJ(this->FileName, data);
  else if (ext == "ply")
    status = cmp::readPLY(this->FileName, data);
  else
  {
    status = readWithVTK(this->FileName, ext, fromVTK);
    if (status.ok())
    {
      status = cmp::bridge::toTriangleMesh(fromVTK, data.mesh);
      if (!status.ok())
        status = cmp::Status::error(std::string(this->FileName) + ": " + status.message());
    }
  }
  if (!status.ok())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  this->UpdateProgress(0.5);
  const int welded = cmp::weldIdenticalPoints(data);
  vtkSmartPointer<vtkPolyData> surface = cmp::bridge::toPolyData(data.mesh);
  if (fromVTK)
  {
    copyWeldedPointData(fromVTK->GetPointData(), data.fileToMeshPoint, surface);
    surface->GetCellData()->ShallowCopy(fromVTK->GetCellData());
  }
  if (!data.cornerTexCoords.empty())
    addTextureCoordinates(data, surface);
  if (!data.pointProperties.empty() || !data.triangleProperties.empty())
    addPLYAttributes(data, surface);
  if (welded > 0)
    surface->GetFieldData()->AddArray(
      cmp::bridge::valueArray<vtkIdTypeArray>(cmp::bridge::kFileToMeshPointArray, data.fileToMeshPoint));
  cmp::bridge::setFieldValue(surface->GetFieldData(), cmp::bridge::kWeldedPointCountField, welded);
  // Names the model in the messages of the filters downstream (which see one
  // block of a collection at a time, without its name); the folder is left
  // out because it is the same for a whole collection and makes lines long.
  cmp::bridge::setFieldString(surface->GetFieldData(), cmp::bridge::kSourceFileArray,
    std::filesystem::path(this->FileName).filename().string());
  output->ShallowCopy(surface);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPSurfaceReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
