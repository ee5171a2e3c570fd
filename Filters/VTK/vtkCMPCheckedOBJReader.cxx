#include "vtkCMPCheckedOBJReader.h"

#include <cmp/io/MeshFile.h>
#include "vtkCMPFileChecks.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCMPCheckedOBJReader);

int vtkCMPCheckedOBJReader::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const char* name = this->GetFileName();
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (name && *name)
  {
    cmp::MeshFileData data;
    if (cmp::Status s = cmp::readOBJ(name, data); !s.ok())
      return cmp::bridge::refuse(this, output, s.message());
  }
  // VTK's own messages do not name the file: they are said again with it.
  int result = 0;
  const std::string said = cmp::bridge::readWithMessages(this, name ? name : "the input",
    [&] { return this->Superclass::RequestData(request, inputVector, outputVector); }, result);
  return said.empty() ? result : cmp::bridge::refuse(this, output, said);
}
