#include "vtkCMPMeshPCA.h"

#include <cmp/analysis/MeshPCA.h>
#include "vtkCMPConsistentCollection.h"
#include "vtkCMPControllerCommunicator.h"
#include "vtkCMPPolyDataBridge.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <chrono>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkCMPMeshPCA);

vtkCxxSetSmartPointerMacro(vtkCMPMeshPCA, Controller, vtkMultiProcessController);

vtkMultiProcessController* vtkCMPMeshPCA::GetController()
{
  return this->Controller;
}

namespace
{

enum OutputPort
{
  MEAN = 0,
  COEFFICIENTS = 1,
  VARIANCES = 2,
  SYNTHESIS = 3,
  ALIGNED = 4
};

} // namespace

vtkCMPMeshPCA::vtkCMPMeshPCA()
{
  this->Controller = vtkMultiProcessController::GetGlobalController();
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(5);
}

int vtkCMPMeshPCA::FillInputPortInformation(int, vtkInformation* info)
{
  // A single surface is accepted by the pipeline so that the filter can say
  // why it needs a collection.
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkCMPMeshPCA::FillOutputPortInformation(int port, vtkInformation* info)
{
  const char* type = port == COEFFICIENTS || port == VARIANCES ? "vtkTable"
    : port == ALIGNED                                          ? "vtkMultiBlockDataSet"
                                                               : "vtkPolyData";
  info->Set(vtkDataObject::DATA_TYPE_NAME(), type);
  return 1;
}

namespace
{

vtkSmartPointer<vtkDoubleArray> doubleArray(const std::string& name, const Eigen::VectorXd& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfValues(values.size());
  for (Eigen::Index i = 0; i < values.size(); ++i)
    array->SetValue(i, values[i]);
  return array;
}

vtkSmartPointer<vtkPolyData> meanOutput(const cmp::MeshPCA& pca, const cmp::bridge::ConsistentCollection& collection)
{
  vtkSmartPointer<vtkPolyData> mean = cmp::bridge::toPolyData(pca.mean, collection.triangles);
  cmp::bridge::copyCorrespondenceArrays(collection.surfaces.surfaces.empty() ? nullptr : collection.surfaces.surfaces[0], mean);
  for (int k = 0; k < pca.modeCount(); ++k)
  {
    // One standard deviation along the mode: what a user warps by.
    const std::vector<cmp::Vec3> displacement = pca.modeDisplacements(k);
    const double deviation = std::sqrt(pca.variances[k]);
    auto mode = vtkSmartPointer<vtkDoubleArray>::New();
    mode->SetName((cmp::bridge::kModeArrayPrefix + std::to_string(k)).c_str());
    mode->SetNumberOfComponents(3);
    mode->SetNumberOfTuples(static_cast<vtkIdType>(displacement.size()));
    for (std::size_t v = 0; v < displacement.size(); ++v)
    {
      const cmp::Vec3 d = deviation * displacement[v];
      mode->SetTypedTuple(static_cast<vtkIdType>(v), d.data());
    }
    mean->GetPointData()->AddArray(mode);
  }
  return mean;
}

vtkSmartPointer<vtkTable> coefficientTable(const cmp::MeshPCA& pca, const std::vector<std::string>& names)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  auto model = vtkSmartPointer<vtkStringArray>::New();
  model->SetName(cmp::bridge::kModelColumn);
  auto index = vtkSmartPointer<vtkIntArray>::New();
  index->SetName(cmp::bridge::kIndexColumn);
  for (int i = 0; i < pca.modelCount(); ++i)
  {
    model->InsertNextValue(i < static_cast<int>(names.size()) ? names[i] : "");
    index->InsertNextValue(i);
  }
  table->AddColumn(model);
  table->AddColumn(index);
  for (int k = 0; k < pca.modeCount(); ++k)
    table->AddColumn(doubleArray(cmp::bridge::kCoefficientColumnPrefix + std::to_string(k), pca.coefficients.col(k)));
  return table;
}

vtkSmartPointer<vtkTable> varianceTable(const cmp::MeshPCA& pca)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  auto mode = vtkSmartPointer<vtkIntArray>::New();
  mode->SetName(cmp::bridge::kModeColumn);
  Eigen::VectorXd cumulative(pca.modeCount());
  double sum = 0.0;
  for (int k = 0; k < pca.modeCount(); ++k)
  {
    mode->InsertNextValue(k);
    cumulative[k] = (sum += pca.explainedVarianceRatios[k]);
  }
  table->AddColumn(mode);
  table->AddColumn(doubleArray(cmp::bridge::kVarianceArray, pca.variances));
  table->AddColumn(doubleArray(cmp::bridge::kStandardDeviationColumn, pca.variances.cwiseSqrt()));
  table->AddColumn(doubleArray(cmp::bridge::kExplainedVarianceRatioArray, pca.explainedVarianceRatios));
  table->AddColumn(doubleArray(cmp::bridge::kCumulativeRatioColumn, cumulative));
  return table;
}

/// The aligned models as the input's blocks, arrays kept.
void alignedOutput(const cmp::bridge::ConsistentCollection& collection, const cmp::ShapeList& aligned,
  vtkDataObject* input, vtkMultiBlockDataSet* output)
{
  std::vector<vtkSmartPointer<vtkPolyData>> results;
  for (std::size_t m = 0; m < aligned.size(); ++m)
  {
    auto model = vtkSmartPointer<vtkPolyData>::New();
    model->ShallowCopy(collection.surfaces.surfaces[m]);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(aligned[m].size()));
    for (std::size_t v = 0; v < aligned[m].size(); ++v)
      points->SetPoint(static_cast<vtkIdType>(v), aligned[m][v].data());
    model->SetPoints(points);
    results.push_back(model);
  }
  if (vtkMultiBlockDataSet::SafeDownCast(input))
    cmp::bridge::assembleOutput(input, output, results);
  else if (!results.empty())
    output->SetBlock(0, results.front());
}

} // namespace

int vtkCMPMeshPCA::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const auto start = std::chrono::steady_clock::now();
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  cmp::bridge::ControllerCommunicator communicator(this->Controller);
  cmp::bridge::ConsistentCollection collection;
  if (cmp::Status s = cmp::bridge::readConsistentCollection(input, communicator, collection); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  if (collection.globalModelCount < 2)
  {
    vtkErrorMacro("principal components need a collection of at least two models (the input has "
      << collection.globalModelCount << "): give the multiblock of remeshes Semi-Regular Remesher makes");
    return 0;
  }
  this->UpdateProgress(0.1);
  cmp::ShapeList aligned;
  cmp::ShapeAlignment alignment;
  if (cmp::Status s = cmp::bridge::alignCollection(collection,
        static_cast<cmp::bridge::CollectionAlignment>(this->Alignment), communicator, aligned, &alignment);
      !s.ok())
  {
    vtkErrorMacro(<< "alignment: " << s.message());
    return 0;
  }
  this->UpdateProgress(0.5);
  cmp::MeshPCA pca;
  if (cmp::Status s = cmp::computeMeshPCA(aligned, this->NumberOfModes, communicator, pca); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  this->UpdateProgress(0.8);

  // Synthesis: a model's coefficients, or one standard deviation on the
  // chosen mode from the mean.
  if (this->SynthesisModel < -1 || this->SynthesisModel >= pca.modelCount())
  {
    vtkErrorMacro("SynthesisModel " << this->SynthesisModel << " is not a model: give -1 (the mean) or 0.."
                                    << pca.modelCount() - 1);
    return 0;
  }
  if (this->SynthesisMode < -1 || this->SynthesisMode >= std::max(1, pca.modeCount()))
  {
    vtkErrorMacro("SynthesisMode " << this->SynthesisMode << " is not a mode: give -1 (none) or 0.."
                                   << pca.modeCount() - 1 << " (" << pca.modeCount() << " modes were kept)");
    return 0;
  }
  Eigen::VectorXd factors = Eigen::VectorXd::Constant(pca.modeCount(), this->SynthesisAllModesFactor);
  Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(pca.modeCount());
  if (this->SynthesisMode >= 0 && this->SynthesisMode < pca.modeCount())
  {
    factors[this->SynthesisMode] *= this->SynthesisModeFactor;
    coefficients[this->SynthesisMode] = std::sqrt(pca.variances[this->SynthesisMode]);
  }
  if (this->SynthesisModel >= 0)
    coefficients = pca.coefficients.row(this->SynthesisModel).transpose();
  std::vector<cmp::Vec3> synthesized;
  if (cmp::Status s = cmp::synthesizeShape(pca, coefficients, factors, synthesized); !s.ok())
  {
    vtkErrorMacro(<< "synthesis: " << s.message());
    return 0;
  }

  alignedOutput(collection, aligned, input, vtkMultiBlockDataSet::GetData(outputVector, ALIGNED));
  // The collection's results once, on the first process.
  if (communicator.rank() != 0)
    return 1;
  vtkSmartPointer<vtkPolyData> mean = meanOutput(pca, collection);
  vtkFieldData* field = mean->GetFieldData();
  cmp::bridge::setFieldValue(field, cmp::bridge::kModelCountField, pca.modelCount());
  cmp::bridge::setFieldValue(field, cmp::bridge::kModeCountField, pca.modeCount());
  field->AddArray(doubleArray(cmp::bridge::kVarianceArray, pca.variances));
  field->AddArray(doubleArray(cmp::bridge::kExplainedVarianceRatioArray, pca.explainedVarianceRatios));
  cmp::bridge::setFieldValue(field, cmp::bridge::kTotalVarianceField, pca.totalVariance);
  cmp::bridge::setFieldValue(field, cmp::bridge::kAlignmentIterationsField, alignment.iterations);
  cmp::bridge::setFieldValue(
    field, cmp::bridge::kAlignmentConvergedField, this->Alignment == NO_ALIGNMENT || alignment.converged);
  cmp::bridge::setFieldValue(field, cmp::bridge::kPCASecondsField,
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  vtkPolyData::GetData(outputVector, MEAN)->ShallowCopy(mean);
  vtkTable::GetData(outputVector, COEFFICIENTS)->ShallowCopy(coefficientTable(pca, collection.globalNames));
  vtkTable::GetData(outputVector, VARIANCES)->ShallowCopy(varianceTable(pca));
  vtkSmartPointer<vtkPolyData> synthesis = cmp::bridge::toPolyData(synthesized, collection.triangles);
  cmp::bridge::copyCorrespondenceArrays(collection.surfaces.surfaces.empty() ? nullptr : collection.surfaces.surfaces[0], synthesis);
  vtkPolyData::GetData(outputVector, SYNTHESIS)->ShallowCopy(synthesis);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPMeshPCA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Alignment: " << this->Alignment << "\n";
  os << indent << "NumberOfModes: " << this->NumberOfModes << "\n";
  os << indent << "SynthesisModel: " << this->SynthesisModel << "\n";
  os << indent << "SynthesisMode: " << this->SynthesisMode << "\n";
  os << indent << "SynthesisModeFactor: " << this->SynthesisModeFactor << "\n";
  os << indent << "SynthesisAllModesFactor: " << this->SynthesisAllModesFactor << "\n";
}
