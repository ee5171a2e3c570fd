#include "vtkCMPSurfaceReader.h"

#include <cmp/io/MeshFile.h>
#include <cmp/io/STLCheck.h>
#include "vtkCMPFileChecks.h"
#include "vtkCMPPolyDataBridge.h"

#include <vtkAbstractPolyDataReader.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <type_traits>

vtkStandardNewMacro(vtkCMPSurfaceReader);

namespace
{

using cmp::bridge::addPLYAttributes;
using cmp::bridge::copyWeldedPointData;
using cmp::bridge::ErrorCollector;

/// Reads STL or VTP with VTK's readers and triangulates polygons.
cmp::Status readWithVTK(const std::string& path, const std::string& extension, vtkSmartPointer<vtkPolyData>& result)
{
  // VTK 9.2's readers trust the files' counts and types: check them first.
  if (extension == "stl")
  {
    if (cmp::Status s = cmp::checkSTLFile(path); !s.ok())
      return s;
  }
  else if (cmp::Status s = cmp::bridge::checkVTPFileWithVTK(path); !s.ok())
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
    const std::string detail = errors.lastLine();
    return cmp::Status::error("cannot read '" + path + "' as " + extension + (detail.empty() ? "" : ": " + detail));
  }
  return {};
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
