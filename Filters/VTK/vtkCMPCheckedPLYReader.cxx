#include "vtkCMPCheckedPLYReader.h"

#include <cmp/io/MeshFile.h>
#include "vtkCMPFileChecks.h"
#include "vtkCMPPolyDataBridge.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCMPCheckedPLYReader);

int vtkCMPCheckedPLYReader::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const char* name = this->GetFileName();
  if (!name || !*name || this->GetReadFromInputString())
    return this->Superclass::RequestData(request, inputVector, outputVector);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  cmp::MeshFileData data;
  if (cmp::Status s = cmp::readPLY(name, data); !s.ok())
    return cmp::bridge::refuse(this, output, s.message());
  // VTK's own PLY parser is never given the file (it aborts on files the
  // core reads, for example an ASCII file without a last newline or damaged
  // binary lists): the points, the faces as triangles and the attributes
  // VTK's reader would make, from the core's reading.
  vtkSmartPointer<vtkPolyData> surface = cmp::bridge::toPolyData(data.mesh);
  cmp::bridge::addPLYAttributes(data, surface);
  output->ShallowCopy(surface);
  return 1;
}
