#include "vtkCMPWaveletDetailTransfer.h"

#include <cmp/analysis/DetailTransfer.h>
#include <cmp/analysis/LoopWavelet.h>
#include <cmp/remesh/SemiRegularRemesher.h>
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
#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <string>

vtkStandardNewMacro(vtkCMPWaveletDetailTransfer);

namespace
{

using cmp::bridge::intArray;
using cmp::bridge::kVertexLevelArray;
using cmp::bridge::kLevelArray;

/// What the transfer needs of one model, the same on every rank.
struct SharedModel
{
  Eigen::MatrixXd positions;       ///< One row per vertex.
  std::vector<int> vertexLevels;   ///< `VertexLevel` (coarse model only).
  std::vector<int> triangleLevels; ///< Cell array `Level` (coarse model only).
};

/// Reads `model`'s positions and, with `withLevels`, the remesher's level
/// arrays into one flat vector of doubles (what the communicator moves).
cmp::Status packModel(const std::vector<cmp::Vec3>& positions, vtkPolyData* model, bool withLevels,
  std::vector<double>& flat)
{
  flat.clear();
  for (const cmp::Vec3& p : positions)
    flat.insert(flat.end(), { p.x(), p.y(), p.z() });
  if (!withLevels)
    return {};
  vtkDataArray* vertexLevels = model->GetPointData()->GetArray(kVertexLevelArray);
  vtkDataArray* triangleLevels = model->GetCellData()->GetArray(kLevelArray);
  if (!vertexLevels || !triangleLevels)
    return cmp::Status::error(std::string("the model has no ") + (vertexLevels ? "cell" : "point") + " array '" +
      (vertexLevels ? kLevelArray : kVertexLevelArray) +
      "': give the output of Semi-Regular Remesher, whose levels the wavelets follow");
  for (vtkIdType v = 0; v < vertexLevels->GetNumberOfTuples(); ++v)
    flat.push_back(vertexLevels->GetComponent(v, 0));
  for (vtkIdType t = 0; t < triangleLevels->GetNumberOfTuples(); ++t)
    flat.push_back(triangleLevels->GetComponent(t, 0));
  return {};
}

/// Sends global model `index` from the rank that holds it to every rank.
/// Collective.
cmp::Status shareModel(const cmp::bridge::ConsistentCollection& collection, int index, bool withLevels,
  cmp::Communicator& communicator, SharedModel& out)
{
  const std::vector<int> localCounts = communicator.allGather(static_cast<int>(collection.positions.size()));
  int owner = 0, first = 0;
  while (index >= first + localCounts[owner])
    first += localCounts[owner++];
  const std::size_t n = collection.pointCount, triangles = collection.triangles.size();
  std::vector<double> flat;
  cmp::Status local;
  if (communicator.rank() == owner)
  {
    const int m = index - first;
    local = packModel(collection.positions[m], collection.surfaces.surfaces[m], withLevels, flat);
    if (!local.ok())
      local = cmp::Status::error(collection.surfaces.labels[m] + local.message());
  }
  if (cmp::Status s = cmp::agreeOnStatus(local, communicator); !s.ok())
    return s;
  flat.resize(3 * n + (withLevels ? n + triangles : 0));
  communicator.broadcast(flat.data(), flat.size(), owner);
  out.positions = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(flat.data(), n, 3);
  if (withLevels)
  {
    out.vertexLevels.assign(flat.begin() + 3 * n, flat.begin() + 4 * n);
    out.triangleLevels.assign(flat.begin() + 4 * n, flat.end());
  }
  return {};
}

/// The wavelet transform of the collection's connectivity, which must be a
/// uniform remesh numbered level by level.
cmp::Status buildTransform(const cmp::bridge::ConsistentCollection& collection, const SharedModel& coarse,
  cmp::LoopWaveletTransform& transform)
{
  cmp::SemiRegularMesh mesh;
  mesh.triangles = collection.triangles;
  mesh.levelOfVertex = coarse.vertexLevels;
  mesh.levelOfTriangle = coarse.triangleLevels;
  mesh.locations.resize(collection.pointCount); // the transform reads no base location: left unset
  mesh.level = mesh.levelOfTriangle.empty()
    ? 0
    : *std::max_element(mesh.levelOfTriangle.begin(), mesh.levelOfTriangle.end());
  if (cmp::Status s = transform.build(mesh); !s.ok())
    return cmp::Status::error("the collection is not a uniform semi-regular remesh (remesh with adaptive "
                              "tolerance 0): " +
      s.message());
  return {};
}

vtkSmartPointer<vtkPolyData> toPolyData(const Eigen::MatrixXd& positions, const std::vector<cmp::Triangle>& triangles)
{
  std::vector<cmp::Vec3> points(positions.rows());
  for (Eigen::Index v = 0; v < positions.rows(); ++v)
    points[v] = positions.row(v).transpose();
  return cmp::bridge::toPolyData(points, triangles);
}

vtkSmartPointer<vtkDoubleArray> coefficientArray(const char* name, const Eigen::MatrixXd& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(static_cast<int>(values.cols()));
  array->SetNumberOfTuples(values.rows());
  for (Eigen::Index v = 0; v < values.rows(); ++v)
    for (Eigen::Index c = 0; c < values.cols(); ++c)
      array->SetTypedComponent(v, static_cast<int>(c), values(v, c));
  return array;
}

/// The result's approximation at every level, each with the point arrays of
/// `finest` at its vertices (the first V_l of the finest level).
cmp::Status levelMeshes(const cmp::LoopWaveletTransform& transform, const cmp::WaveletCoefficients& coefficients,
  vtkPolyData* finest, vtkMultiBlockDataSet* out)
{
  out->SetNumberOfBlocks(transform.level() + 1);
  for (int l = 0; l <= transform.level(); ++l)
  {
    Eigen::MatrixXd positions;
    if (cmp::Status s = transform.synthesize(coefficients, l, positions); !s.ok())
      return s;
    vtkSmartPointer<vtkPolyData> mesh = toPolyData(positions, transform.triangles(l));
    vtkPointData* points = mesh->GetPointData();
    points->CopyAllocate(finest->GetPointData(), positions.rows());
    for (vtkIdType v = 0; v < positions.rows(); ++v)
      points->CopyData(finest->GetPointData(), v, v);
    out->SetBlock(l, mesh);
    out->GetMetaData(l)->Set(vtkCompositeDataSet::NAME(), ("Level " + std::to_string(l)).c_str());
  }
  return {};
}

} // namespace

vtkCMPWaveletDetailTransfer::vtkCMPWaveletDetailTransfer()
{
  this->Controller = vtkMultiProcessController::GetGlobalController();
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
}

vtkCxxSetSmartPointerMacro(vtkCMPWaveletDetailTransfer, Controller, vtkMultiProcessController);

vtkMultiProcessController* vtkCMPWaveletDetailTransfer::GetController()
{
  return this->Controller;
}

void vtkCMPWaveletDetailTransfer::SetDetailWeights(const std::vector<double>& weights)
{
  if (weights != this->DetailWeights)
  {
    this->DetailWeights = weights;
    this->Modified();
  }
}

void vtkCMPWaveletDetailTransfer::AddDetailWeight(double weight)
{
  this->DetailWeights.push_back(weight);
  this->Modified();
}

void vtkCMPWaveletDetailTransfer::RemoveAllDetailWeights()
{
  if (!this->DetailWeights.empty())
  {
    this->DetailWeights.clear();
    this->Modified();
  }
}

int vtkCMPWaveletDetailTransfer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkCMPWaveletDetailTransfer::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkMultiBlockDataSet");
  return 1;
}

int vtkCMPWaveletDetailTransfer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const auto start = std::chrono::steady_clock::now();
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkMultiBlockDataSet* levelsOutput = vtkMultiBlockDataSet::GetData(outputVector, 1);
  // The properties are the same on every rank: a bad one stops them all.
  if (!cmp::isRemeshLevel(this->LastCoarseLevel))
  {
    vtkErrorMacro(<< cmp::remeshLevelProblem("LastCoarseLevel", this->LastCoarseLevel));
    return 0;
  }
  cmp::bridge::ControllerCommunicator communicator(this->Controller);
  cmp::bridge::ConsistentCollection collection;
  if (cmp::Status s = cmp::bridge::readConsistentCollection(input, communicator, collection); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  for (const auto& [property, index] : { std::make_pair("CoarseModel", this->CoarseModel),
         std::make_pair("DetailModel", this->DetailModel) })
    if (index < 0 || index >= collection.globalModelCount)
    {
      vtkErrorMacro(<< property << " " << index << ": the collection has " << collection.globalModelCount
                    << " models (0 to " << collection.globalModelCount - 1 << ")");
      return 0;
    }

  SharedModel coarse, detail;
  if (cmp::Status s = shareModel(collection, this->CoarseModel, true, communicator, coarse); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  if (cmp::Status s = shareModel(collection, this->DetailModel, false, communicator, detail); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  // Everything below is local: rank 0 computes and outputs, as the other
  // collection filters do.
  if (communicator.rank() != 0)
    return 1;

  cmp::LoopWaveletTransform transform;
  if (cmp::Status s = buildTransform(collection, coarse, transform); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  const int finest = transform.level();
  cmp::DetailSchedule schedule = this->DetailWeights;
  if (schedule.empty())
  {
    if (this->LastCoarseLevel > finest)
    {
      vtkErrorMacro("LastCoarseLevel " << this->LastCoarseLevel << " is above the remesh's finest level " << finest
                                       << ": give 0 to " << finest);
      return 0;
    }
    schedule = cmp::detailsOfBAbove(finest, this->LastCoarseLevel);
  }
  else if (static_cast<int>(schedule.size()) != finest + 1)
  {
    vtkErrorMacro("DetailWeights has " << schedule.size() << " entries; the level-" << finest << " remesh needs "
                                       << finest + 1 << " (the coarsest level, then levels 1 to " << finest << ")");
    return 0;
  }
  else if (!std::all_of(schedule.begin(), schedule.end(), [](double w) { return std::isfinite(w); }))
  {
    vtkErrorMacro("DetailWeights has a NaN or infinite entry");
    return 0;
  }
  this->UpdateProgress(0.2);

  const cmp::DetailFrame frame = this->LocalFrames ? cmp::DetailFrame::Local : cmp::DetailFrame::Global;
  cmp::WaveletCoefficients coarseCoefficients, detailCoefficients, blended;
  Eigen::MatrixXd positions;
  cmp::Status status = transform.analyze(coarse.positions, frame, coarseCoefficients);
  if (status.ok())
    status = transform.analyze(detail.positions, frame, detailCoefficients);
  if (status.ok())
    status = cmp::transferDetails(coarseCoefficients, detailCoefficients, schedule, blended,
      this->ScaleDetailsToCoarseSize ? cmp::DetailScaling::RelativeToCoarseSize : cmp::DetailScaling::Absolute);
  if (status.ok())
    status = transform.synthesize(blended, positions);
  if (!status.ok())
  {
    vtkErrorMacro(<< status.message());
    return 0;
  }
  this->UpdateProgress(0.7);

  vtkSmartPointer<vtkPolyData> result = toPolyData(positions, collection.triangles);
  cmp::bridge::copyCorrespondenceArrays(
    collection.surfaces.surfaces.empty() ? nullptr : collection.surfaces.surfaces[0], result);
  // A rank 0 that holds no model still gives the levels the wavelets used.
  if (!result->GetPointData()->HasArray(kVertexLevelArray))
    result->GetPointData()->AddArray(intArray(kVertexLevelArray, coarse.vertexLevels));
  if (!result->GetCellData()->HasArray(kLevelArray))
    result->GetCellData()->AddArray(intArray(kLevelArray, coarse.triangleLevels));
  vtkPointData* points = result->GetPointData();
  points->AddArray(coefficientArray(cmp::bridge::kWaveletCoefficientsArray, blended.values));
  points->AddArray(coefficientArray(cmp::bridge::kCoarseModelCoefficientsArray, coarseCoefficients.values));
  points->AddArray(coefficientArray(cmp::bridge::kDetailModelCoefficientsArray, detailCoefficients.values));
  Eigen::MatrixXd magnitude = blended.values.rowwise().norm();
  magnitude.topRows(transform.vertexCount(0)).setZero(); // positions there, not details
  points->AddArray(coefficientArray(cmp::bridge::kDetailMagnitudeArray, magnitude));

  if (cmp::Status s = levelMeshes(transform, blended, result, levelsOutput); !s.ok())
  {
    vtkErrorMacro(<< s.message());
    return 0;
  }
  auto weights = vtkSmartPointer<vtkDoubleArray>::New();
  weights->SetName(cmp::bridge::kDetailWeightsArray);
  for (double w : schedule)
    weights->InsertNextValue(w);
  result->GetFieldData()->AddArray(weights);
  cmp::bridge::setFieldValue(result->GetFieldData(), cmp::bridge::kTransferSecondsField,
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  output->ShallowCopy(result);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCMPWaveletDetailTransfer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CoarseModel: " << this->CoarseModel << "\n"
     << indent << "DetailModel: " << this->DetailModel << "\n"
     << indent << "LastCoarseLevel: " << this->LastCoarseLevel << "\n"
     << indent << "DetailWeights:";
  for (double w : this->DetailWeights)
    os << " " << w;
  os << "\n"
     << indent << "LocalFrames: " << this->LocalFrames << "\n"
     << indent << "ScaleDetailsToCoarseSize: " << this->ScaleDetailsToCoarseSize << "\n";
}
