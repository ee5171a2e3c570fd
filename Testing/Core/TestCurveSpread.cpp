#include <cmp/layout/CurveSpread.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>

using namespace cmp;

TEST(CurveSpread, CurvesAlongTheOctahedronsEdgesLeaveEveryLandmarkAQuarterTurnApart)
{
  test::ParameterizedModel sphere;
  ASSERT_TRUE(test::parameterizedSphere(test::orderedOctahedronDomain(), 4, sphere).ok());
  const std::vector<double> gaps = largestCurveGaps(sphere.net);
  ASSERT_EQ(gaps.size(), 6u);
  for (double gap : gaps)
    EXPECT_NEAR(gap, 90.0, 10.0);
}

TEST(CurveSpread, FindsTheLandmarkWhereTheStraightenedCurvesLeaveBunched)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  // Measured: traced with requeued swirling curves only, 384's curves leave
  // its landmark 8 (the outside of the left hind leg's top) within 13
  // degrees (a 347-degree gap), where its remesh kept 3 folds after repair.
  // The default tracer keeps the shorter net traced with waiting curves
  // there, which spreads them (183 degrees at most); 387's net, the same
  // either way, 182.
  NetTracerOptions requeueOnly;
  requeueOnly.retraceWaiting = false;
  const struct
  {
    std::string name;
    NetTracerOptions tracing;
    bool bunched;
  } cases[] = { { "384", requeueOnly, true }, { "384", {}, false }, { "387", {}, false } };
  for (const auto& c : cases)
  {
    const std::string what = c.name + (c.bunched ? " requeued" : "");
    test::ParameterizedModel model;
    ASSERT_TRUE(test::parameterizeOnDomain(test::landmarkedRealModel(c.name), domain, model, c.tracing).ok()) << what;
    const CurveGap widest = widestCurveGap(model.net);
    ASSERT_GE(widest.baseVertex, 0) << what;
    const std::vector<double> gaps = largestCurveGaps(model.net);
    EXPECT_EQ(gaps[widest.baseVertex], widest.degrees) << what;
    for (double gap : gaps)
      EXPECT_LE(gap, widest.degrees) << what;
    if (c.bunched)
    {
      EXPECT_EQ(domain.featureIds[widest.baseVertex], 8);
      EXPECT_GT(widest.degrees, 300.0);
    }
    else
      EXPECT_LT(widest.degrees, 250.0) << what;
    std::cout << what << ": widest curve gap " << widest.degrees << " degrees at landmark "
              << domain.featureIds[widest.baseVertex] << "\n";
  }
}

TEST(CurveSpread, AnEmptyNetHasNoGap)
{
  const TracedNet empty;
  EXPECT_TRUE(largestCurveGaps(empty).empty());
  EXPECT_EQ(widestCurveGap(empty).baseVertex, -1);
}
