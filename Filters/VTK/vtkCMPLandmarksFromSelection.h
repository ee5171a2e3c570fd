#pragma once
/// \file vtkCMPLandmarksFromSelection.h
/// \brief Landmarks picked in the GUI: a point selection, or an ordered id
///        list, turned into the `FeatureId` array.

#include "CMPFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <vector>

/// \brief Marks the selected points of a surface as landmarks: the k-th
///        selected point gets `FeatureId` k, every other point -1.
///
/// Input 0: the surface. Input 1 (optional): a vtkSelection of points, such
/// as ParaView's current selection (points picked interactively, by id, or
/// by a query); its ids are taken in the order the selection lists them,
/// node by node, which for ids typed or picked one at a time is pick order.
/// A selection of another kind (frustum, values, ...) is converted to point
/// ids first, whose order is then the mesh's. `PointIds`, when given, is
/// used instead of the selection: the explicit, ordered way.
///
/// The landmarks are the paper's F feature points (§2, "Basic Setup").
/// Errors, reported with `vtkErrorMacro` (no output): no selection and no
/// ids, a cell selection, an id out of range, the same point twice, a
/// count different from `ExpectedLandmarkCount` (when >= 0), and every
/// surface check of the other filters (closed, manifold, finite
/// coordinates).
class CMPFILTERS_EXPORT vtkCMPLandmarksFromSelection : public vtkPolyDataAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPLandmarksFromSelection* New();
  vtkTypeMacro(vtkCMPLandmarksFromSelection, vtkPolyDataAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Connects the selection to input port 1.
  void SetSelectionConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// \brief The landmark point ids in feature order; when not empty they
  ///        are used instead of the selection.
  void SetPointIds(const std::vector<int>& ids);
  /// \brief Appends one id (ParaView's repeatable property).
  void AddPointId(int id);
  /// \brief Removes every id, so that the selection is used.
  void RemoveAllPointIds();
  /// \brief The explicit landmark ids.
  const std::vector<int>& GetPointIds() const { return this->PointIds; }

  /// \brief Number of landmarks required; -1 (default) accepts any.
  vtkSetMacro(ExpectedLandmarkCount, int);
  /// \brief Number of landmarks required.
  vtkGetMacro(ExpectedLandmarkCount, int);

protected:
  vtkCMPLandmarksFromSelection();
  ~vtkCMPLandmarksFromSelection() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPLandmarksFromSelection(const vtkCMPLandmarksFromSelection&) = delete;
  void operator=(const vtkCMPLandmarksFromSelection&) = delete;

  std::vector<int> PointIds;
  int ExpectedLandmarkCount = -1;
};
