#include <cmp/map/Straighten.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

namespace cmp
{

Status checkStraightenOptions(const StraightenOptions& options)
{
  std::ostringstream problem;
  const NetStraightenerOptions& net = options.net;
  if (net.maxSweeps < 0)
    problem << "MaximumSweeps must be 0 or more (it is " << net.maxSweeps << ")";
  else if (!(net.tolerance >= 0.0) || !std::isfinite(net.tolerance))
    problem << "Tolerance must be a finite number >= 0 (it is " << net.tolerance << ")";
  else if (!(net.snapTolerance >= 0.0 && net.snapTolerance < 0.5))
    problem << "SnapTolerance must be at least 0 and below 0.5 (it is " << net.snapTolerance << ")";
  else if (options.freeCurves && options.map.maximumIterations < 0)
    problem << "MapIterations must be 0 or more (it is " << options.map.maximumIterations << ")";
  else if (options.freeCurvesMaximumTriangles < 0)
    problem << "FreeCurvesMaximumTriangles must be 0 (no limit) or more (it is "
            << options.freeCurvesMaximumTriangles << ")";
  if (!problem.str().empty())
    return Status::error(problem.str());
  return options.freeCurves ? checkGlobalMapOptions(options.map) : Status{};
}

Status straighten(const TracedNet& traced, const BaseDomain& domain, StraightenedNet& out, PatchParameterization& map,
  const StraightenOptions& options, StraightenReport* report)
{
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const Clock::time_point start = Clock::now();
  StraightenReport local;
  StraightenReport& r = report ? *report : local;
  r = StraightenReport{};
  if (Status status = checkStraightenOptions(options); !status.ok())
    return status;

  NetStraightenerOptions netOptions = options.net;
  netOptions.progress = options.progress;
  StraightenedNet straight;
  Clock::time_point part = Clock::now();
  Status status = straightenNet(traced, domain, straight, netOptions, &r.net);
  r.straightenSeconds = since(part);
  r.straightenedNetLength = r.net.netLengthAfter;
  PatchParameterization parameterization;
  if (status.ok())
  {
    part = Clock::now();
    status = parameterizePatches(straight.net, domain, parameterization, options.patches);
    if (!status.ok())
    {
      // A straightened patch that cannot be mapped onto its base triangle:
      // the traced curves instead (no sweep), which the map frees all the
      // same, rather than failing the model.
      NetStraightenerOptions traceOnly = netOptions;
      traceOnly.maxSweeps = 0;
      StraightenedNet kept;
      NetStraightenerReport keptReport;
      if (straightenNet(traced, domain, kept, traceOnly, &keptReport).ok() &&
        parameterizePatches(kept.net, domain, parameterization, options.patches).ok())
      {
        r.tracedCurvesKept = "the straightened net could not be parameterized (" + status.message() +
          "), so the traced curves were kept";
        straight = std::move(kept);
        r.net = keptReport;
        r.straightenedNetLength = r.net.netLengthAfter;
        status = Status();
      }
    }
    r.parameterizeSeconds = since(part);
  }
  const bool tooLarge = options.freeCurvesMaximumTriangles > 0 &&
    traced.mesh.triangleCount() > options.freeCurvesMaximumTriangles;
  if (status.ok() && options.freeCurves && tooLarge)
  {
    std::ostringstream reason;
    reason << "the surface has " << traced.mesh.triangleCount() << " triangles, more than FreeCurvesMaximumTriangles ("
           << options.freeCurvesMaximumTriangles
           << "): the whole-surface map would take its Newton steps on all of them, for many minutes; raise the "
              "limit (0: none) to free the curves anyway, or simplify the surface";
    r.freeCurves.applied = false;
    r.freeCurves.reason = reason.str();
  }
  else if (status.ok() && options.freeCurves)
  {
    part = Clock::now();
    StraightenedNet moved;
    PatchParameterization movedMap;
    status = freeCurves(straight, domain, parameterization, options.map, moved, movedMap, &r.freeCurves);
    if (!status.ok())
    {
      // The straightened net is a valid layout: keep it, and say why the
      // curves stay (a patch map that starts crushed cannot start the map).
      r.freeCurves.applied = false;
      r.freeCurves.reason = status.message();
      status = Status();
    }
    else
    {
      straight = std::move(moved);
      parameterization = std::move(movedMap);
      if (r.freeCurves.applied)
      {
        r.net.netLengthAfter = netLength(straight.net);
        r.net.areaVariationAfter = areaVariation(patchAreas(straight.net, domain.mesh.triangleCount()));
      }
    }
    r.mapSeconds = since(part);
  }
  if (status.ok())
  {
    out = std::move(straight);
    map = std::move(parameterization);
  }
  r.seconds = since(start);
  return status;
}

} // namespace cmp
