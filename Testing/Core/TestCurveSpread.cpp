#include <cmp/layout/CurveSpread.h>
#include "TestMeshes.h"

#include <gtest/gtest.h>

#include <iostream>

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
  // Measured: 384's landmark 8 (the outside of the left hind leg's top),
  // where its remesh keeps 3 folds after repair, 347 degrees; 387, whose
  // remesh keeps none, 182.
  for (const std::string name : { "384", "387" })
  {
    test::ParameterizedModel model;
    ASSERT_TRUE(test::parameterizeOnDomain(test::landmarkedRealModel(name), domain, model).ok()) << name;
    const CurveGap widest = widestCurveGap(model.net);
    ASSERT_GE(widest.baseVertex, 0) << name;
    const std::vector<double> gaps = largestCurveGaps(model.net);
    EXPECT_EQ(gaps[widest.baseVertex], widest.degrees) << name;
    for (double gap : gaps)
      EXPECT_LE(gap, widest.degrees) << name;
    if (name == "384")
    {
      EXPECT_EQ(domain.featureIds[widest.baseVertex], 8);
      EXPECT_GT(widest.degrees, 300.0);
    }
    else
      EXPECT_LT(widest.degrees, 250.0) << name;
    std::cout << name << ": widest curve gap " << widest.degrees << " degrees at landmark "
              << domain.featureIds[widest.baseVertex] << "\n";
  }
}

TEST(CurveSpread, AnEmptyNetHasNoGap)
{
  const TracedNet empty;
  EXPECT_TRUE(largestCurveGaps(empty).empty());
  EXPECT_EQ(widestCurveGap(empty).baseVertex, -1);
}
