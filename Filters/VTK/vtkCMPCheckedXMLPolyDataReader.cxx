#include "vtkCMPCheckedXMLPolyDataReader.h"

#include "vtkCMPFileChecks.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <filesystem>
#include <system_error>

vtkStandardNewMacro(vtkCMPCheckedXMLPolyDataReader);

namespace
{

std::time_t fileTime(const std::string& path)
{
  std::error_code error;
  const auto time = std::filesystem::last_write_time(path, error);
  return error ? 0 : static_cast<std::time_t>(time.time_since_epoch().count());
}

} // namespace

int vtkCMPCheckedXMLPolyDataReader::ReadXMLInformation()
{
  // A stream or string input (ReadFromInputString) is VTK's to read: only
  // files are checked.
  const char* name = this->GetFileName();
  if (name && *name && !this->GetReadFromInputString())
  {
    const std::string path = name;
    const std::time_t time = fileTime(path);
    if (path != this->CheckedFile || time != this->CheckedTime)
    {
      const cmp::Status s = cmp::bridge::checkVTPFileWithVTK(path);
      this->CheckedFile = path;
      this->CheckedTime = time;
      this->CheckFailure = s.ok() ? std::string() : s.message();
    }
    if (!this->CheckFailure.empty())
      return cmp::bridge::refuse(this, nullptr, this->CheckFailure);
  }
  return this->Superclass::ReadXMLInformation();
}

int vtkCMPCheckedXMLPolyDataReader::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const char* file = this->GetFileName();
  const std::string path = file ? file : "the input";
  // VTK's RequestData runs even when the information could not be read, and
  // then reads past its parser: a refused file stops here, and says why to
  // whoever asked for the data.
  if (!this->GetReadFromInputString() && file && *file && !this->CheckFailure.empty() && this->CheckedFile == file)
    return cmp::bridge::refuse(this, output, this->CheckFailure);
  // VTK's own messages (a damaged array, say) do not name the file: they are
  // said again with it.
  int result = 0;
  const std::string said = cmp::bridge::readWithMessages(
    this, path, [&] { return this->Superclass::RequestData(request, inputVector, outputVector); }, result);
  if (!said.empty())
    return cmp::bridge::refuse(this, output, said);
  if (output)
  {
    if (cmp::Status s = cmp::bridge::checkCellPointIds(output, path); !s.ok())
      return cmp::bridge::refuse(this, output, s.message());
  }
  return result;
}
