#include <cmp/io/VTPCheck.h>
#include "TestData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

using namespace cmp;
using test::writeTempFile;

namespace
{

// Base64 of `bytes`, padded.
std::string base64(const std::string& bytes)
{
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3)
  {
    unsigned bits = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size())
      bits |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size())
      bits |= static_cast<unsigned char>(bytes[i + 2]);
    out += digits[(bits >> 18) & 63];
    out += digits[(bits >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(bits >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[bits & 63] : '=';
  }
  return out;
}

std::string littleEndian32(std::uint32_t value)
{
  std::string out;
  for (int b = 0; b < 4; ++b)
    out.push_back(static_cast<char>((value >> (8 * b)) & 0xff));
  return out;
}

// VTK's inline binary: the header (byte count) and the data encoded apart.
std::string inlineBinary(const std::string& data)
{
  return base64(littleEndian32(static_cast<std::uint32_t>(data.size()))) + base64(data);
}

// A one-triangle PolyData whose point and field arrays are given.
std::string polyData(const std::string& fieldArrays, const std::string& pointsArray)
{
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
         "  <PolyData>\n"
         "    <FieldData>\n" +
    fieldArrays +
    "    </FieldData>\n"
    "    <Piece NumberOfPoints=\"3\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
    "NumberOfPolys=\"1\">\n"
    "      <Points>\n" +
    pointsArray +
    "      </Points>\n"
    "      <Polys>\n"
    "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>\n"
    "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3</DataArray>\n"
    "      </Polys>\n"
    "    </Piece>\n"
    "  </PolyData>\n"
    "</VTKFile>\n";
}

const std::string kAsciiPoints = "        <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n"
                                 "          0 0 0 1 0 0 0 1 0\n"
                                 "        </DataArray>\n";

std::string check(const std::string& name, const std::string& text)
{
  return checkVTPFile(writeTempFile(name, text)).message();
}

} // namespace

TEST(VTPCheck, AcceptsWellFormedAsciiAndBinaryArrays)
{
  std::string floats;
  for (int k = 0; k < 9; ++k)
  {
    const float value = k % 4 == 0 ? 1.0f : 0.0f;
    floats.append(reinterpret_cast<const char*>(&value), sizeof(value)); // the test machine is little endian
  }
  const std::string binaryPoints =
    "        <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">\n          " +
    inlineBinary(floats) + "\n        </DataArray>\n";
  const std::string strings = "      <Array type=\"String\" Name=\"SourceFile\" NumberOfTuples=\"1\" format=\"ascii\">"
                              "97 46 111 102 102 0</Array>\n";
  EXPECT_EQ(check("ok-ascii.vtp", polyData(strings, kAsciiPoints)), "");
  EXPECT_EQ(check("ok-binary.vtp", polyData("", binaryPoints)), "");
}

TEST(VTPCheck, RefusesAnUnknownArrayType)
{
  // VTK 9.2's XML reader segfaults on it.
  const std::string points = "        <DataArray type=\"Float33\" NumberOfComponents=\"3\" format=\"ascii\">\n"
                             "          0 0 0 1 0 0 0 1 0\n        </DataArray>\n";
  const std::string message = check("type.vtp", polyData("", points));
  EXPECT_NE(message.find("type.vtp:8: DataArray has type 'Float33', which VTK does not know"), std::string::npos)
    << message;
}

TEST(VTPCheck, RefusesComponentCountsVTKCannotRead)
{
  // A connectivity array with 2^32 - 1 components: VTK 9.2 spins on it.
  std::string text = polyData("", kAsciiPoints);
  const std::string connectivity = "Name=\"connectivity\" format";
  text.replace(text.find(connectivity), connectivity.size(),
    "Name=\"connectivity\" NumberOfComponents=\"4294967295\" format");
  std::string message = check("components.vtp", text);
  EXPECT_NE(message.find("components.vtp:13: DataArray 'connectivity': NumberOfComponents '4294967295' is larger "
                         "than VTK reads"),
    std::string::npos)
    << message;
  text = polyData("", kAsciiPoints);
  text.replace(text.find(connectivity), connectivity.size(), "Name=\"connectivity\" NumberOfComponents=\"3\" format");
  message = check("cell-components.vtp", text);
  EXPECT_NE(message.find("DataArray 'connectivity': NumberOfComponents is 3, but a cell array has 1"),
    std::string::npos)
    << message;
}

TEST(VTPCheck, RefusesAStringArrayClaimingMoreTuplesThanItHolds)
{
  // 2^31 tuples: VTK 9.2 allocates them and aborts with bad_alloc.
  // VTK writes string arrays as <Array>.
  const std::string ascii = "      <Array type=\"String\" Name=\"SourceFile\" NumberOfTuples=\"2147483648\" "
                            "format=\"ascii\">97 0</Array>\n";
  std::string message = check("strings.vtp", polyData(ascii, kAsciiPoints));
  EXPECT_NE(message.find("strings.vtp:5: Array 'SourceFile' needs 2147483648 values (2147483648 tuples of 1) "
                         "but has 2"),
    std::string::npos)
    << message;
  const std::string binary = "      <DataArray type=\"String\" Name=\"SourceFile\" NumberOfTuples=\"2147483648\" "
                             "format=\"binary\">" +
    inlineBinary(std::string("a\0", 2)) + "</DataArray>\n";
  message = check("strings-binary.vtp", polyData(binary, kAsciiPoints));
  EXPECT_NE(message.find("strings-binary.vtp:5: DataArray 'SourceFile': needs 2147483648 bytes but its data has 2"),
    std::string::npos)
    << message;
}

TEST(VTPCheck, RefusesCountsAndHeadersTheDataCannotBack)
{
  std::string text = polyData("", kAsciiPoints);
  text.replace(text.find("NumberOfPoints=\"3\""), 18, "NumberOfPoints=\"4000000000\"");
  std::string message = check("points.vtp", text);
  EXPECT_NE(message.find("points.vtp:8: DataArray needs 12000000000 values"), std::string::npos) << message;

  // A binary block header claiming more bytes than follow.
  const std::string lying = "        <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">" +
    base64(littleEndian32(1u << 30)) + base64(std::string(36, '\0')) + "</DataArray>\n";
  message = check("header.vtp", polyData("", lying));
  EXPECT_NE(message.find("header.vtp:8: DataArray: its header claims 1073741824 bytes but 36 follow"), std::string::npos)
    << message;

  const std::string garbage = "        <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">@@@@"
                              "</DataArray>\n";
  message = check("base64.vtp", polyData("", garbage));
  EXPECT_NE(message.find("base64.vtp:8: DataArray: its binary data is not base64"), std::string::npos) << message;

  const std::string components = "        <DataArray type=\"Float32\" NumberOfComponents=\"-3\" format=\"ascii\">"
                                 "0</DataArray>\n";
  message = check("components.vtp", polyData("", components));
  EXPECT_NE(message.find("components.vtp:8: DataArray: NumberOfComponents '-3' is not a positive integer"),
    std::string::npos)
    << message;
}

TEST(VTPCheck, RefusesAppendedDataThatIsMissingOrTooShort)
{
  const std::string header = "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                             "<PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"0\"><Points>\n"
                             "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/>\n"
                             "</Points></Piece></PolyData>\n";
  // 72 bytes of points announced, 8 present.
  std::string message =
    check("appended.vtp", header + "<AppendedData encoding=\"raw\">\n_" + littleEndian32(8) + std::string(8, '\0') +
        "\n</AppendedData>\n</VTKFile>\n");
  EXPECT_NE(message.find("appended.vtp:3: DataArray: needs 72 bytes but its data has 8"), std::string::npos)
    << message;
  message = check("noappended.vtp", header + "</VTKFile>\n");
  EXPECT_NE(message.find("noappended.vtp:3: DataArray: appended, but the file has no AppendedData"), std::string::npos)
    << message;
  // VTK's parser reads block headers from the wrong place (and allocated
  // for 15 s in a fuzzed file) when anything but blanks precedes the '_'.
  message = check("underscore.vtp", header + "<AppendedData encoding=\"raw\">\n<AppendedData encoding=\"raw\">\n_" +
      littleEndian32(72) + std::string(72, '\0') + "\n</AppendedData>\n</VTKFile>\n");
  EXPECT_NE(message.find("underscore.vtp:6: AppendedData does not start with '_'"), std::string::npos) << message;
  message = check("offset.vtp", header + "<AppendedData encoding=\"base64\">_" + std::string("AAAA") +
      "</AppendedData></VTKFile>\n");
  EXPECT_NE(message.find("offset.vtp:3: DataArray: no room for its 4-byte header"), std::string::npos) << message;
}

TEST(VTPCheck, RefusesMalformedXMLAndOtherFiles)
{
  EXPECT_NE(check("empty.vtp", "").find("empty.vtp:1: no XML element"), std::string::npos);
  EXPECT_NE(check("garbage.vtp", "<VTKFile>oops").find("garbage.vtp:1: not a PolyData file"), std::string::npos);
  EXPECT_NE(check("grid.vtp", "<VTKFile type=\"ImageData\"></VTKFile>").find("not a PolyData file"),
    std::string::npos);
  std::string message = check("unclosed.vtp", "<VTKFile type=\"PolyData\">\n<PolyData>\n<Piece>\n");
  EXPECT_NE(message.find("unclosed.vtp:4: the file ends inside <Piece> (line 3)"), std::string::npos) << message;
  message = check("crossed.vtp", "<VTKFile type=\"PolyData\">\n<PolyData>\n</Piece>\n</VTKFile>\n");
  EXPECT_NE(message.find("crossed.vtp:3: </Piece> closes <PolyData> (line 2)"), std::string::npos) << message;
  message = check("quote.vtp", "<VTKFile type=\"PolyData\">\n<PolyData a=b>\n");
  EXPECT_NE(message.find("quote.vtp:2: attribute 'a' of <PolyData> has no quoted value"), std::string::npos)
    << message;
  message = check("order.vtp", "<VTKFile type=\"PolyData\" byte_order=\"MiddleEndian\"></VTKFile>");
  EXPECT_NE(message.find("order.vtp:1: unknown byte_order 'MiddleEndian'"), std::string::npos) << message;
  EXPECT_NE(checkVTPFile("/nonexistent/a.vtp").message().find("cannot open '/nonexistent/a.vtp'"), std::string::npos);
}

TEST(VTPCheck, RefusesMoreStringsThanDeclared)
{
  // VTK 9.2 stores every string it splits off into an array of the declared
  // size: a second string where one is declared crashed it (found by fuzzing).
  const std::string ascii = "      <Array type=\"String\" Name=\"SourceFile\" NumberOfTuples=\"1\" format=\"ascii\">"
                            "97 0 98 0</Array>\n";
  std::string message = check("twostrings.vtp", polyData(ascii, kAsciiPoints));
  EXPECT_NE(message.find("twostrings.vtp:5: Array 'SourceFile' holds 2 strings but declares 1"), std::string::npos)
    << message;
  const std::string binary = "      <Array type=\"String\" Name=\"SourceFile\" NumberOfTuples=\"1\" format=\"binary\">" +
    inlineBinary(std::string("a\0b\0", 4)) + "</Array>\n";
  message = check("twostrings-binary.vtp", polyData(binary, kAsciiPoints));
  EXPECT_NE(message.find("twostrings-binary.vtp:5: Array 'SourceFile' holds 2 strings but declares 1"),
    std::string::npos)
    << message;
}

TEST(VTPCheck, RefusesALastOffsetBeyondTheConnectivity)
{
  // VTK 9.2 sizes the connectivity it reads by the last offset: a fuzzed
  // offset made it abort allocating 2^41 values.
  std::string text = polyData("", kAsciiPoints);
  text.replace(text.find("format=\"ascii\">3</DataArray>"), 28, "format=\"ascii\">3000000000000</DataArray>");
  std::string message = check("offset-ascii.vtp", text);
  EXPECT_NE(message.find("offset-ascii.vtp:14: DataArray 'offsets': its last offset, 3000000000000, is beyond the 3 "
                         "values of the connectivity"),
    std::string::npos)
    << message;
  std::string offsets(8, '\0');
  offsets[5] = '\x02'; // 2^41, little endian Int64
  text = polyData("", kAsciiPoints);
  text.replace(text.find("format=\"ascii\">3</DataArray>"), 28, "format=\"binary\">" + inlineBinary(offsets) + "</DataArray>");
  message = check("offset-binary.vtp", text);
  EXPECT_NE(message.find("offset-binary.vtp:14: DataArray 'offsets': its last offset, 2199023255552, is beyond"),
    std::string::npos)
    << message;
}

namespace
{

// VTK's inline binary for a compressed array whose blocks are `blocks`,
// each "compressed" by storing it as it is (the decompressor below copies).
std::string compressedBinary(const std::vector<std::string>& blocks)
{
  std::string header = littleEndian32(static_cast<std::uint32_t>(blocks.size())) +
    littleEndian32(static_cast<std::uint32_t>(blocks.front().size())) +
    littleEndian32(static_cast<std::uint32_t>(blocks.back().size()));
  std::string data;
  for (const std::string& block : blocks)
  {
    header += littleEndian32(static_cast<std::uint32_t>(block.size()));
    data += block;
  }
  return base64(header) + base64(data);
}

// A "decompressor" of stored blocks, counting its calls.
struct StoredBlocks
{
  int calls = 0;
  bool fail = false;
  VTPDecompressor decompressor()
  {
    return [this](const std::string& compressor, const unsigned char* in, std::size_t inSize, unsigned char* out,
             std::size_t outSize)
    {
      ++calls;
      if (fail || compressor != "vtkZLibDataCompressor" || inSize != outSize)
        return false;
      std::copy(in, in + inSize, out);
      return true;
    };
  }
};

// polyData() compressed, with `offsets` and `strings` (field data) given.
std::string compressedPolyData(const std::string& strings, const std::string& offsets)
{
  std::string text = polyData(strings, kAsciiPoints);
  text.replace(text.find("header_type=\"UInt32\""), 20, "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\"");
  text.replace(text.find("format=\"ascii\">3</DataArray>"), 28, "format=\"binary\">" + offsets + "</DataArray>");
  return text;
}

std::string int64(std::uint64_t value)
{
  std::string out;
  for (int b = 0; b < 8; ++b)
    out.push_back(static_cast<char>((value >> (8 * b)) & 0xff));
  return out;
}

} // namespace

TEST(VTPCheck, ChecksCompressedValuesWithADecompressor)
{
  // A compressed last offset of 2^41 made VTK 9.2 abort; it straddles the
  // two blocks here.
  const std::string offset = int64(std::uint64_t(1) << 41);
  const std::string path = writeTempFile("offset-compressed.vtp",
    compressedPolyData("", compressedBinary({ offset.substr(0, 4), offset.substr(4) })));
  EXPECT_EQ(checkVTPFile(path).message(), "") << "without a decompressor compressed values are not seen";
  StoredBlocks stored;
  std::string message = checkVTPFile(path, stored.decompressor()).message();
  EXPECT_NE(message.find("offset-compressed.vtp:14: DataArray 'offsets': its last offset, 2199023255552, is beyond "
                         "the 3 values of the connectivity"),
    std::string::npos)
    << message;
  EXPECT_EQ(stored.calls, 2) << "both blocks hold part of the last value";

  const std::string strings = "      <Array type=\"String\" Name=\"SourceFile\" NumberOfTuples=\"1\" format=\"binary\">" +
    compressedBinary({ std::string("a\0b", 3), std::string("\0", 1) }) + "</Array>\n";
  message = checkVTPFile(writeTempFile("strings-compressed.vtp", compressedPolyData(strings, compressedBinary({ int64(3) }))),
    stored.decompressor())
              .message();
  EXPECT_NE(message.find("strings-compressed.vtp:5: Array 'SourceFile' holds 2 strings but declares 1"),
    std::string::npos)
    << message;
}

TEST(VTPCheck, AcceptsGoodCompressedValuesAndRefusesABlockThatDoesNotDecompress)
{
  const std::string strings = "      <Array type=\"String\" Name=\"SourceFile\" NumberOfTuples=\"2\" format=\"binary\">" +
    compressedBinary({ std::string("a\0b", 3), std::string("\0", 1) }) + "</Array>\n";
  const std::string path =
    writeTempFile("good-compressed.vtp", compressedPolyData(strings, compressedBinary({ int64(3) })));
  StoredBlocks stored;
  EXPECT_EQ(checkVTPFile(path, stored.decompressor()).message(), "");
  EXPECT_EQ(stored.calls, 3);
  stored.fail = true;
  const std::string message = checkVTPFile(path, stored.decompressor()).message();
  EXPECT_NE(message.find("good-compressed.vtp:5: Array 'SourceFile': its compressed block 0 does not decompress to 3 "
                         "bytes"),
    std::string::npos)
    << message;
}
