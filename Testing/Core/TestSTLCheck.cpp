#include <cmp/io/STLCheck.h>
#include "TestData.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

using namespace cmp;
using test::writeTempFile;

namespace
{

// A binary STL: an 80-byte header starting with `header`, the count
// `claimed`, and `triangles` records of 50 bytes.
std::string binarySTL(const std::string& header, std::uint32_t claimed, int triangles)
{
  std::string out = header + std::string(80 - header.size(), ' ');
  for (int b = 0; b < 4; ++b)
    out.push_back(static_cast<char>((claimed >> (8 * b)) & 0xff));
  for (int t = 0; t < triangles; ++t)
    out += std::string("\x01\x80\x00\x3f", 4) + std::string(46, '\0');
  return out;
}

} // namespace

TEST(STLCheck, AcceptsABinarySTLOfTheRightSizeAndAnyASCIISTL)
{
  EXPECT_TRUE(checkSTLFile(writeTempFile("right.stl", binarySTL("binary", 3, 3))).ok());
  const std::string ascii = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                            "endloop\nendfacet\nendsolid t\n";
  EXPECT_TRUE(checkSTLFile(writeTempFile("ascii.stl", ascii)).ok());
}

TEST(STLCheck, RefusesACountTheSizeDisagreesWithEvenUnderASolidHeader)
{
  // VTK takes this file for binary (NUL bytes), whatever its first word.
  const Status s = checkSTLFile(writeTempFile("solid.stl", binarySTL("solid looks like text", 2147483647u, 2)));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("solid.stl' as stl: the header announces 2147483647 triangles (107374182434 bytes) "
                             "but the file has 184 bytes"),
    std::string::npos)
    << s.message();
  const Status fewer = checkSTLFile(writeTempFile("fewer.stl", binarySTL("binary", 1, 2)));
  EXPECT_NE(fewer.message().find("announces 1 triangles (134 bytes) but the file has 184 bytes"), std::string::npos)
    << fewer.message();
}

TEST(STLCheck, RefusesAShortBinaryAnEmptyAndAMissingFile)
{
  const Status shortFile = checkSTLFile(writeTempFile("short.stl", std::string(40, '\0')));
  EXPECT_NE(shortFile.message().find("a binary STL has at least 84 bytes, this file 40"), std::string::npos)
    << shortFile.message();
  EXPECT_NE(checkSTLFile(writeTempFile("empty.stl", "")).message().find("this file 0"), std::string::npos);
  const Status missing = checkSTLFile("/nonexistent/folder/missing.stl");
  EXPECT_NE(missing.message().find("missing.stl' as stl: cannot open it"), std::string::npos) << missing.message();
}

TEST(STLCheck, TakesForBinaryWhatVTKMayTakeForBinary)
{
  EXPECT_TRUE(mayBeBinarySTL(""));
  EXPECT_TRUE(mayBeBinarySTL(std::string("solid a\0", 8)));
  EXPECT_FALSE(mayBeBinarySTL("solid a\nfacet normal 0 0 1\n"));
  // One byte in 50 that is not text is enough.
  EXPECT_TRUE(mayBeBinarySTL(std::string(49, 'a') + "\x80"));
  EXPECT_FALSE(mayBeBinarySTL(std::string(50, 'a') + "\x80"));
}
