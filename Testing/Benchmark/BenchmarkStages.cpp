#include "BenchmarkStages.h"

#include "Subdivision.h"

namespace cmp::bench
{
namespace
{

/// \brief `read`: parse the file and weld coincident points, as every
///        consumer of a file does before anything else.
Status readStage(ModelContext& ctx)
{
  ctx.file = MeshFileData{};
  const Status status = fileExtension(ctx.spec.meshPath) == "obj" ? readOBJ(ctx.spec.meshPath, ctx.file)
                                                                   : readOFF(ctx.spec.meshPath, ctx.file);
  if (status.ok())
    weldIdenticalPoints(ctx.file);
  return status;
}

/// \brief `subdivide`: refine the file mesh for the large model. Original
///        vertices keep their ids, so the model's landmark file still applies.
Status subdivideStage(ModelContext& ctx)
{
  ctx.subdivided = TriangleMesh{};
  ctx.subdivided = subdivideMidpoint(ctx.file.mesh, ctx.spec.subdivisionLevels);
  return {};
}

/// \brief `check`: the input check every stage of the pipeline runs first.
Status checkStage(ModelContext& ctx)
{
  ctx.surfaceCheck = checkSurface(ctx.surface());
  if (!ctx.surfaceCheck.ok())
    return Status::error("surface check: " + ctx.surfaceCheck.message);
  return {};
}

/// \brief `landmarks`: read the landmark file and map it to welded vertex ids.
Status landmarksStage(ModelContext& ctx)
{
  ctx.landmarks.clear();
  return readLandmarkFile(ctx.spec.landmarkPath, ctx.surface(), ctx.file.fileToMeshPoint, ctx.landmarks);
}

/// \brief `base_domain`: decimate the surface down to its landmarks (L0).
Status baseDomainStage(ModelContext& ctx)
{
  ctx.domain = BaseDomain{};
  ctx.domainReport = BaseDomainBuilderReport{};
  return buildBaseDomain(ctx.surface(), ctx.landmarks, ctx.domain, {}, &ctx.domainReport);
}

bool isSubdivided(const ModelSpec& spec)
{
  return spec.subdivisionLevels > 0;
}

} // namespace

const std::vector<Stage>& pipelineStages()
{
  // Pipeline order. A later stage appends one line here, e.g.
  //   { "tracer", traceStage },
  static const std::vector<Stage> stages = {
    { "read", readStage, {} },
    { "subdivide", subdivideStage, isSubdivided },
    { "check", checkStage, {} },
    { "landmarks", landmarksStage, {} },
    { "base_domain", baseDomainStage, {} },
  };
  return stages;
}

bool stageApplies(const Stage& stage, const ModelSpec& spec)
{
  return !stage.appliesTo || stage.appliesTo(spec);
}

} // namespace cmp::bench
