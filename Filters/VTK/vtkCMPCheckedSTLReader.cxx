#include "vtkCMPCheckedSTLReader.h"

#include <cmp/io/STLCheck.h>
#include "vtkCMPFileChecks.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCMPCheckedSTLReader);

int vtkCMPCheckedSTLReader::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const char* name = this->GetFileName();
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (name && *name)
  {
    if (cmp::Status s = cmp::checkSTLFile(name); !s.ok())
      return cmp::bridge::refuse(this, output, s.message());
  }
  // VTK's own messages do not name the file: they are said again with it.
  int result = 0;
  const std::string said = cmp::bridge::readWithMessages(this, name ? name : "the input",
    [&] { return this->Superclass::RequestData(request, inputVector, outputVector); }, result);
  return said.empty() ? result : cmp::bridge::refuse(this, output, said);
}
