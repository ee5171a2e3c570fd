#include "FilterTestUtilities.h"

#include "vtkCMPBaseDomainBuilder.h"
#include "vtkCMPFeatureNetTracer.h"
#include "vtkCMPLandmarksFromFile.h"
#include "vtkCMPNetStraightener.h"
#include "vtkCMPSurfaceReader.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMassProperties.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace cmp::test
{

RunResult run(vtkAlgorithm* algorithm)
{
  RunResult result;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&result.error);
  callback->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void* callData)
    {
      auto* error = static_cast<std::string*>(clientData);
      if (error->empty() && callData)
        *error = static_cast<const char*>(callData);
    });
  const unsigned long tag = algorithm->AddObserver(vtkCommand::ErrorEvent, callback);
  const bool ok = algorithm->GetExecutive()->Update() != 0;
  algorithm->RemoveObserver(tag);
  result.succeeded = ok && result.error.empty();
  return result;
}

std::string octahedronOFF(bool open)
{
  std::string text = "OFF\n6 " + std::string(open ? "7" : "8") +
    " 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
    "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n";
  if (!open)
    text += "3 0 3 5\n";
  return text;
}

void setFeatureIds(vtkPolyData* surface, std::vector<int> ids)
{
  vtkNew<vtkIntArray> array;
  array->SetName("FeatureId");
  ids.resize(surface->GetNumberOfPoints(), -1);
  for (int id : ids)
    array->InsertNextValue(id);
  surface->GetPointData()->AddArray(array);
}

vtkSmartPointer<vtkPolyData> readLandmarked(const std::string& mesh, const std::string& landmarks)
{
  vtkNew<vtkCMPSurfaceReader> reader;
  reader->SetFileName(mesh.c_str());
  vtkNew<vtkCMPLandmarksFromFile> assign;
  assign->SetInputConnection(reader->GetOutputPort());
  assign->SetLandmarkFile(landmarks.c_str());
  const RunResult result = run(assign);
  EXPECT_TRUE(result.succeeded) << result.error;
  return assign->GetOutput();
}

double areaOf(vtkPolyData* surface)
{
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(surface);
  mass->Update();
  return mass->GetSurfaceArea();
}

double fieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetComponent(0, 0) : NAN;
}

std::string examplesDir()
{
  return CMP_EXAMPLES_DIR;
}

vtkSmartPointer<vtkPolyData> parameterized(vtkPolyData* surface, vtkPolyData* l0, bool freeCurves)
{
  vtkNew<vtkCMPFeatureNetTracer> tracer;
  tracer->SetInputData(0, surface);
  tracer->SetInputData(1, l0);
  vtkNew<vtkCMPNetStraightener> straightener;
  straightener->SetInputConnection(0, tracer->GetOutputPort(0));
  straightener->SetInputData(1, l0);
  straightener->SetFreeCurves(freeCurves);
  const RunResult result = run(straightener);
  EXPECT_TRUE(result.succeeded) << result.error;
  return straightener->GetOutput(0);
}

vtkSmartPointer<vtkPolyData> baseDomainOf(vtkPolyData* surface)
{
  vtkNew<vtkCMPBaseDomainBuilder> builder;
  builder->SetInputData(surface);
  EXPECT_TRUE(run(builder).succeeded);
  return builder->GetOutput();
}

vtkSmartPointer<vtkPolyData> withFeatures0And1Swapped(vtkPolyData* l0)
{
  auto swapped = vtkSmartPointer<vtkPolyData>::New();
  swapped->DeepCopy(l0);
  vtkDataArray* ids = swapped->GetPointData()->GetArray("FeatureId");
  for (vtkIdType p = 0; p < ids->GetNumberOfTuples(); ++p)
  {
    const double f = ids->GetComponent(p, 0);
    ids->SetComponent(p, 0, f == 0 ? 1 : f == 1 ? 0 : f);
  }
  return swapped;
}

vtkSmartPointer<vtkPolyData> tetrahedronBaseDomain(const std::string& fileName)
{
  vtkNew<vtkCMPSurfaceReader> reader;
  reader->SetFileName(
    writeTempFile(fileName, "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n")
      .c_str());
  EXPECT_TRUE(run(reader).succeeded);
  setFeatureIds(reader->GetOutput(), { 0, 1, 2, 3 });
  return reader->GetOutput();
}

vtkSmartPointer<vtkMultiBlockDataSet> parameterizedExamples(vtkPolyData* l0)
{
  const std::string folder = examplesDir() + "/";
  auto models = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  const std::vector<std::array<std::string, 3>> files = { { "blob", "blob.off", "blob.vts" },
    { "capsule", "capsule.obj", "capsule.pinned" }, { "peanut", "peanut.off", "peanut.csv" } };
  for (unsigned m = 0; m < files.size(); ++m)
  {
    models->SetBlock(m, parameterized(readLandmarked(folder + files[m][1], folder + files[m][2]), l0));
    models->GetMetaData(m)->Set(vtkCompositeDataSet::NAME(), files[m][0].c_str());
  }
  return models;
}

vtkSmartPointer<vtkMultiBlockDataSet> blocksOf(std::initializer_list<vtkPolyData*> surfaces)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  unsigned b = 0;
  for (vtkPolyData* surface : surfaces)
    blocks->SetBlock(b++, surface);
  return blocks;
}

vtkSmartPointer<vtkPolyData> withNaNAt(vtkPolyData* surface, vtkIdType point)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(surface);
  copy->GetPoints()->SetPoint(point, std::numeric_limits<double>::quiet_NaN(), 0, 0);
  return copy;
}

void addCornerTCoords(vtkPolyData* surface, int uAxis, int vAxis)
{
  addCornerTCoords(surface, [&](const double* point, vtkIdType) { return std::array<double, 2>{ point[uAxis], point[vAxis] }; });
}

void addCornerTCoords(
  vtkPolyData* surface, const std::function<std::array<double, 2>(const double* point, vtkIdType cell)>& uvAt)
{
  vtkNew<vtkDoubleArray> corners;
  corners->SetName("CornerTCoords");
  corners->SetNumberOfComponents(6);
  corners->SetNumberOfTuples(surface->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    for (int k = 0; k < 3; ++k)
    {
      const std::array<double, 2> uv = uvAt(surface->GetPoint(ids->GetId(k)), c);
      corners->SetComponent(c, 2 * k, uv[0]);
      corners->SetComponent(c, 2 * k + 1, uv[1]);
    }
  }
  surface->GetCellData()->AddArray(corners);
}

int cornersNotAtTheirPoints(vtkPolyData* surface, int uAxis, int vAxis, double tolerance)
{
  vtkDataArray* corners = surface->GetCellData()->GetArray("CornerTCoords");
  if (!corners)
    return static_cast<int>(3 * surface->GetNumberOfCells());
  int bad = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    for (int k = 0; k < 3; ++k)
      bad += std::abs(corners->GetComponent(c, 2 * k) - surface->GetPoint(ids->GetId(k))[uAxis]) > tolerance ||
        std::abs(corners->GetComponent(c, 2 * k + 1) - surface->GetPoint(ids->GetId(k))[vAxis]) > tolerance;
  }
  return bad;
}

} // namespace cmp::test
