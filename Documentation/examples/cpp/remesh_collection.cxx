// A C++ VTK application that remeshes a collection of landmarked surfaces
// with one connectivity and writes the remeshes and their mean shape:
//
//   remesh_collection OUTPUT_FOLDER LEVEL MESH LANDMARKS [MESH LANDMARKS ...]
//
// The base domain L0 is built from the first model. Every stage is a VTK
// algorithm of the CMP::Filters module, connected as any VTK pipeline; the
// only project-specific thing is the order of the stages. Exit status 0 on
// success, 1 (with the filter's message on stderr) if a stage fails, 2 for
// wrong arguments. Built and run by the test suite (example.Cpp).

#include "vtkCMPBaseDomainBuilder.h"
#include "vtkCMPFeatureNetTracer.h"
#include "vtkCMPLandmarksFromFile.h"
#include "vtkCMPMeshPCA.h"
#include "vtkCMPNetStraightener.h"
#include "vtkCMPSemiRegularRemesher.h"
#include "vtkCMPSurfaceReader.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkLogger.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace
{

/// Prints a filter's error message (vtkErrorMacro sends it as an event,
/// "ERROR: In FILE, line N" then "CLASS (ADDRESS): MESSAGE") as
/// "CLASS: MESSAGE", instead of VTK's default output window.
void printError(vtkObject* caller, unsigned long, void*, void* message)
{
  std::string text = static_cast<const char*>(message);
  if (const auto colon = text.find("): "); colon != std::string::npos)
    text = text.substr(colon + 3);
  while (!text.empty() && text.back() == '\n')
    text.pop_back();
  std::cerr << caller->GetClassName() << ": " << text << "\n";
}

/// Updates `algorithm`; false (and its message on stderr) if it failed.
bool update(vtkAlgorithm* algorithm)
{
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(printError);
  algorithm->AddObserver(vtkCommand::ErrorEvent, onError);
  const bool ok = algorithm->GetExecutive()->Update() != 0;
  algorithm->RemoveObserver(onError);
  return ok;
}

/// A surface read from `mesh` with `FeatureId` from `landmarks`.
vtkSmartPointer<vtkPolyData> readLandmarked(const std::string& mesh, const std::string& landmarks)
{
  vtkNew<vtkCMPSurfaceReader> reader;
  reader->SetFileName(mesh.c_str());
  vtkNew<vtkCMPLandmarksFromFile> marker;
  marker->SetInputConnection(reader->GetOutputPort());
  marker->SetLandmarkFile(landmarks.c_str());
  if (!update(marker))
    return nullptr;
  return marker->GetOutput();
}

std::string stem(const std::string& path)
{
  return std::filesystem::path(path).stem().string();
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc < 5 || (argc - 3) % 2 != 0)
  {
    std::cerr << "usage: remesh_collection OUTPUT_FOLDER LEVEL MESH LANDMARKS [MESH LANDMARKS ...]\n";
    return 2;
  }
  // The filters' messages are printed by printError; the executive's
  // generic "returned failure" log lines would only repeat them.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const std::filesystem::path output = argv[1];
  const int level = std::atoi(argv[2]);
  std::filesystem::create_directories(output);

  // Read every model; the first one gives L0.
  std::vector<vtkSmartPointer<vtkPolyData>> models;
  std::vector<std::string> names;
  for (int i = 3; i + 1 < argc; i += 2)
  {
    vtkSmartPointer<vtkPolyData> model = readLandmarked(argv[i], argv[i + 1]);
    if (!model)
      return 1;
    models.push_back(model);
    names.push_back(stem(argv[i]));
  }
  vtkNew<vtkCMPBaseDomainBuilder> builder;
  builder->SetInputData(models.front());
  if (!update(builder))
    return 1;

  // Trace and straighten each model's patch layout against L0, and collect
  // the parameterized surfaces in one multiblock, named after the files.
  vtkNew<vtkMultiBlockDataSet> parameterized;
  for (std::size_t m = 0; m < models.size(); ++m)
  {
    vtkNew<vtkCMPFeatureNetTracer> tracer;
    tracer->SetInputData(models[m]);
    tracer->SetBaseDomainConnection(builder->GetOutputPort());
    vtkNew<vtkCMPNetStraightener> straightener;
    straightener->SetInputConnection(0, tracer->GetOutputPort(0));
    straightener->SetInputConnection(1, builder->GetOutputPort());
    if (!update(straightener))
    {
      std::cerr << names[m] << " failed\n";
      return 1;
    }
    vtkNew<vtkPolyData> surface;
    surface->ShallowCopy(straightener->GetOutput());
    parameterized->SetBlock(static_cast<unsigned>(m), surface);
    parameterized->GetMetaData(static_cast<unsigned>(m))->Set(vtkCompositeDataSet::NAME(), names[m].c_str());
    std::cout << names[m] << ": parameterized\n";
  }

  // One remesher run for the whole collection: one connectivity.
  vtkNew<vtkCMPSemiRegularRemesher> remesher;
  remesher->SetInputData(0, parameterized);
  remesher->SetInputConnection(1, builder->GetOutputPort());
  remesher->SetLevel(level);
  vtkNew<vtkCMPMeshPCA> pca;
  pca->SetInputConnection(remesher->GetOutputPort(0));
  if (!update(pca))
    return 1;

  vtkNew<vtkXMLMultiBlockDataWriter> collectionWriter;
  collectionWriter->SetInputConnection(remesher->GetOutputPort(0));
  collectionWriter->SetFileName((output / "collection.vtm").c_str());
  vtkNew<vtkXMLPolyDataWriter> meanWriter;
  meanWriter->SetInputConnection(pca->GetOutputPort(0));
  meanWriter->SetFileName((output / "mean.vtp").c_str());
  if (collectionWriter->Write() != 1 || meanWriter->Write() != 1)
  {
    std::cerr << "cannot write into " << output << "\n";
    return 1;
  }
  auto* remeshes = vtkMultiBlockDataSet::SafeDownCast(remesher->GetOutputDataObject(0));
  auto* mean = vtkPolyData::SafeDownCast(pca->GetOutputDataObject(0));
  std::cout << remeshes->GetNumberOfBlocks() << " remeshes at level " << level << ", "
            << mean->GetNumberOfPoints() << " vertices and " << mean->GetNumberOfCells()
            << " triangles each; mean shape and modes in " << (output / "mean.vtp").string() << "\n";
  return 0;
}
