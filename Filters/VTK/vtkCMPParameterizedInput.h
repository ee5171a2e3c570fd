#pragma once
/// \file vtkCMPParameterizedInput.h
/// \brief Reading a straightened (parameterized) surface back from its
///        arrays, and sampling point arrays at located points; shared by
///        the filters that work through the parameterization (private
///        header, not wrapped).

#include <cmp/analysis/AttributeTransfer.h>
#include <cmp/basedomain/BaseDomain.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/map/PatchParameterization.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/layout/OpenSurface.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>

#include "vtkCMPArrayNames.h"

#include <string>
#include <vector>

class vtkDataSetAttributes;
class vtkPolyData;

namespace cmp::bridge
{

/// \brief Reads `BaseTriangle` and `BaseCoordinates` (as Net Straightener
///        and Semi-Regular Remesher write them), checking every value.
Status readParameterization(vtkPolyData* input, int baseTriangleCount, PatchParameterization& out);

/// \brief One parameterized model as the filters that sample it need it:
///        its surface, its layout rebuilt from `PatchId` and its map
///        indexed for point location. Not movable: the index points into
///        the layout.
class ParameterizedInput
{
public:
  /// \brief Remembers `input` (a Net Straightener or Semi-Regular Remesher
  ///        output) and `domain`; both must outlive this object. With
  ///        `holes` (`closeBaseDomain()`'s, outliving this object too),
  ///        `domain` is the closed L0 and the input may be open: its caps
  ///        are closed anew for the layout and the map, while `mesh()`,
  ///        `patchIds()` and `parameterization()` stay the input's.
  ParameterizedInput(const BaseDomain& domain, vtkPolyData* input, const BaseDomainHoles* holes = nullptr);
  ParameterizedInput(const ParameterizedInput&) = delete;
  ParameterizedInput& operator=(const ParameterizedInput&) = delete;

  /// \brief Reads and checks the surface, landmarks, `PatchId` and the
  ///        parameterization, rebuilds the layout and indexes the map.
  Status prepare();

  /// \brief The indexed map (after a successful `prepare()`).
  const ParameterizedSurface& surface() const { return surface_; }
  /// \brief The surface as read.
  const TriangleMesh& mesh() const { return mesh_; }
  /// \brief The layout rebuilt from `PatchId`.
  const TracedNet& net() const { return net_; }
  /// \brief The per-point parameterization as read.
  const PatchParameterization& parameterization() const { return parameterization_; }
  /// \brief The `PatchId` of every triangle as read.
  const std::vector<int>& patchIds() const { return patchIds_; }
  /// \brief The input polydata.
  vtkPolyData* input() const { return input_; }
  /// \brief The base domain the input is parameterized on.
  const BaseDomain& domain() const { return domain_; }

private:
  /// An open input closed against `holes_`: the caps' patches and the
  /// centres' places added to `closedPatchIds` and `closedMap`.
  Status closeInput(const LandmarkList& landmarks, TriangleMesh& closed, LandmarkList& closedLandmarks,
    std::vector<int>& closedPatchIds);

  const BaseDomain& domain_;
  vtkPolyData* input_ = nullptr;
  const BaseDomainHoles* holes_ = nullptr;
  TriangleMesh mesh_;
  PatchParameterization closedMap_; ///< With an open input, the map of its closed layout.
  TracedNet net_;
  PatchParameterization parameterization_;
  std::vector<int> patchIds_;
  ParameterizedSurface surface_;
};

/// \brief The prepared input as a target for attribute transfer: its
///        triangles, their patches and every point's base location.
BaseDomainMesh toBaseDomainMesh(const ParameterizedInput& input);

/// \brief Adds to `output` every array of `input` (but those named in
///        `skip`) evaluated at `samples`: floating-point arrays interpolated
///        with the samples' weights (normals renormalized), integer and
///        other arrays copied from the sample's vertex of largest weight.
///        Attribute roles (normals, texture coordinates, scalars) are kept,
///        except global and pedigree ids, which copies would not keep unique.
void sampleArrays(vtkDataSetAttributes* output, vtkDataSetAttributes* input, const std::vector<SurfacePoint>& samples,
  const std::vector<std::string>& skip);

} // namespace cmp::bridge
