#include <cmp/io/VTPCheck.h>

#include <cmp/io/TextParsing.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

namespace cmp
{
namespace
{

using Count = std::uint64_t;
constexpr Count kHuge = std::numeric_limits<Count>::max();

Count product(Count a, Count b)
{
  return (a != 0 && b > kHuge / a) ? kHuge : a * b;
}

Count sum(Count a, Count b)
{
  return a > kHuge - b ? kHuge : a + b;
}

// Unsigned decimal (surrounding blanks allowed), saturating.
bool parseCount(const std::string& text, Count& value)
{
  const std::size_t b = text.find_first_not_of(" \t\r\n");
  const std::size_t e = text.find_last_not_of(" \t\r\n");
  if (b == std::string::npos)
    return false;
  value = 0;
  for (std::size_t i = b; i <= e; ++i)
  {
    if (text[i] < '0' || text[i] > '9')
      return false;
    value = sum(product(value, 10), static_cast<Count>(text[i] - '0'));
  }
  return true;
}

// Bytes per value of a VTK XML type; 0 for String and Bit, -1 if unknown.
int valueSize(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "Int8", 1 }, { "UInt8", 1 }, { "Int16", 2 },
    { "UInt16", 2 }, { "Int32", 4 }, { "UInt32", 4 }, { "Int64", 8 }, { "UInt64", 8 }, { "Float32", 4 },
    { "Float64", 8 }, { "String", 0 }, { "Bit", 0 } };
  const auto it = sizes.find(type);
  return it == sizes.end() ? -1 : it->second;
}

int base64Value(char c)
{
  if (c >= 'A' && c <= 'Z')
    return c - 'A';
  if (c >= 'a' && c <= 'z')
    return c - 'a' + 26;
  if (c >= '0' && c <= '9')
    return c - '0' + 52;
  if (c == '+')
    return 62;
  if (c == '/')
    return 63;
  return -1;
}

bool isBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// Decodes base64 whose groups may be padded in the middle (VTK encodes a
// block header and its data separately). False on any other character.
bool decodeBase64(const std::string& text, std::size_t begin, std::size_t end, std::string& out)
{
  out.clear();
  int group[4];
  int have = 0, pad = 0;
  for (std::size_t i = begin; i < end; ++i)
  {
    const char c = text[i];
    if (isBlank(c))
      continue;
    if (c == '=')
    {
      if (have < 2)
        return false;
      group[have++] = 0;
      ++pad;
    }
    else
    {
      const int v = base64Value(c);
      if (v < 0 || pad > 0)
        return false;
      group[have++] = v;
    }
    if (have == 4)
    {
      const unsigned bits = (group[0] << 18) | (group[1] << 12) | (group[2] << 6) | group[3];
      out.push_back(static_cast<char>((bits >> 16) & 0xff));
      if (pad < 2)
        out.push_back(static_cast<char>((bits >> 8) & 0xff));
      if (pad < 1)
        out.push_back(static_cast<char>(bits & 0xff));
      have = 0;
      pad = 0;
    }
  }
  return have == 0;
}

// VTK writes numeric arrays as <DataArray> and string arrays as <Array>.
bool isArray(const std::string& tagName)
{
  return tagName == "DataArray" || tagName == "Array";
}

struct Tag
{
  std::string name;
  std::map<std::string, std::string> attributes;
  bool closing = false;
  bool empty = false; // <.../>
  std::size_t begin = 0, end = 0; // '<' and one past '>'
  int line = 0;
};

struct PieceCounts
{
  Count points = 0, verts = 0, lines = 0, strips = 0, polys = 0;
  Count cells() const { return sum(sum(verts, lines), sum(strips, polys)); }
};

// What an array must hold, and where it belongs.
struct ArrayInfo
{
  std::string what; // "path:line: DataArray 'Name'"
  std::string type;
  int size = 0;      // bytes per value; 0 for String and Bit
  Count values = 0;  // tuples times components
  Count need = 0;    // least bytes its values need
  Count offset = 0;  // appended only
  std::string cells; // "piece/Polys" for a cell array's connectivity or offsets
  bool isOffsets = false, isConnectivity = false;
};

// A piece's Verts, Lines, Strips or Polys: VTK sizes the connectivity it
// reads by the last offset, so that offset must not exceed the values the
// connectivity holds.
struct CellArrays
{
  std::string where;
  bool haveLastOffset = false, haveConnectivity = false;
  Count lastOffset = 0, connectivity = 0;
};

// What the uncompressed data of a block says, when it can be read without
// decompressing.
struct BlockData
{
  bool compressed = false;
  Count bytes = 0;       // uncompressed bytes
  std::size_t at = 0;    // where the data starts (for compressed data, the first block's)
  Count blockSize = 0;   // compressed: the uncompressed size of every block but the last
  Count lastSize = 0;    // compressed: the last block's
  std::vector<Count> compressedSizes; // compressed: each block's compressed size
};

class VTPChecker
{
public:
  VTPChecker(const std::string& path, const std::string& text, const VTPDecompressor& decompress)
    : path_(path)
    , text_(text)
    , decompress_(decompress)
  {
  }
  Status check();

private:
  int lineAt(std::size_t pos)
  {
    for (; linePos_ < pos && linePos_ < text_.size(); ++linePos_)
      line_ += text_[linePos_] == '\n' ? 1 : 0;
    return line_;
  }
  Status error(int line, const std::string& what) const { return Status::error(fileLine(path_, line) + what); }
  bool nextTag(Tag& tag, std::string& problem);
  Status checkRoot(const Tag& tag);
  Status checkArray(const Tag& tag, const std::string& parent, const std::string& content);
  Status checkBlocks(const std::string& where, const std::string& decoded, std::size_t at, Count need, BlockData& block);
  Status checkBinaryArray(const ArrayInfo& array, const std::string& data, std::size_t at);
  Status checkStringCount(const ArrayInfo& array, Count strings) const;
  Status decompressBlock(const ArrayInfo& array, const std::string& data, const BlockData& block, Count index,
    std::string& raw) const;
  Status checkCompressedArray(const ArrayInfo& array, const std::string& data, const BlockData& block);
  CellArrays* noteCellArray(const ArrayInfo& array, Count bytes);
  Status checkCellArrays() const;
  Count readValue(const std::string& bytes, std::size_t at, const std::string& type) const;
  Status checkAppended(const Tag& tag);
  Count readHeaderInt(const std::string& bytes, std::size_t at) const;

  const std::string& path_;
  const std::string& text_;
  const VTPDecompressor& decompress_;
  std::string compressor_;
  std::size_t pos_ = 0;
  std::size_t linePos_ = 0;
  int line_ = 1;
  bool bigEndian_ = false;
  std::size_t headerSize_ = 4;
  Count ratio_ = 0; // 0: not compressed
  PieceCounts piece_;
  int pieces_ = 0;
  std::vector<ArrayInfo> appended_;
  std::map<std::string, CellArrays> cellArrays_;
};

bool VTPChecker::nextTag(Tag& tag, std::string& problem)
{
  while (true)
  {
    const std::size_t open = text_.find('<', pos_);
    if (open == std::string::npos)
      return false;
    tag = Tag{};
    tag.begin = open;
    tag.line = lineAt(open);
    if (text_.compare(open, 4, "<!--") == 0)
    {
      const std::size_t close = text_.find("-->", open + 4);
      if (close == std::string::npos)
        return problem = "the file ends inside a comment", false;
      pos_ = close + 3;
      continue;
    }
    if (text_.compare(open, 2, "<?") == 0 || text_.compare(open, 2, "<!") == 0)
    {
      const std::size_t close = text_.find('>', open);
      if (close == std::string::npos)
        return problem = "the file ends inside '<?' or '<!'", false;
      pos_ = close + 1;
      continue;
    }
    std::size_t p = open + 1;
    if (p < text_.size() && text_[p] == '/')
    {
      tag.closing = true;
      ++p;
    }
    const auto nameChar = [](char c)
    { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == ':' || c == '-' || c == '.'; };
    const std::size_t nameBegin = p;
    while (p < text_.size() && nameChar(text_[p]))
      ++p;
    tag.name = text_.substr(nameBegin, p - nameBegin);
    if (tag.name.empty())
      return problem = "a '<' that starts no tag", false;
    while (true)
    {
      while (p < text_.size() && isBlank(text_[p]))
        ++p;
      if (p >= text_.size())
        return problem = "the file ends inside the tag <" + tag.name + ">", false;
      if (text_[p] == '>')
      {
        ++p;
        break;
      }
      if (text_[p] == '/' && !tag.closing && p + 1 < text_.size() && text_[p + 1] == '>')
      {
        tag.empty = true;
        p += 2;
        break;
      }
      if (tag.closing)
        return problem = "a closing tag </" + tag.name + "> with something after its name", false;
      const std::size_t attributeBegin = p;
      while (p < text_.size() && nameChar(text_[p]))
        ++p;
      const std::string attribute = text_.substr(attributeBegin, p - attributeBegin);
      while (p < text_.size() && isBlank(text_[p]))
        ++p;
      if (attribute.empty() || p >= text_.size() || text_[p] != '=')
        return problem = "malformed attribute in <" + tag.name + ">", false;
      ++p;
      while (p < text_.size() && isBlank(text_[p]))
        ++p;
      if (p >= text_.size() || (text_[p] != '"' && text_[p] != '\''))
        return problem = "attribute '" + attribute + "' of <" + tag.name + "> has no quoted value", false;
      const char quote = text_[p++];
      const std::size_t close = text_.find(quote, p);
      if (close == std::string::npos)
        return problem = "the file ends inside attribute '" + attribute + "' of <" + tag.name + ">", false;
      if (!tag.attributes.emplace(attribute, text_.substr(p, close - p)).second)
        return problem = "attribute '" + attribute + "' twice in <" + tag.name + ">", false;
      p = close + 1;
    }
    tag.end = p;
    pos_ = p;
    return true;
  }
}

Status VTPChecker::checkRoot(const Tag& tag)
{
  if (tag.name != "VTKFile" || tag.closing)
    return error(tag.line, "not a VTK XML file (the first element is <" + tag.name + ">, not <VTKFile>)");
  const auto& a = tag.attributes;
  const auto type = a.find("type");
  if (type == a.end() || type->second != "PolyData")
    return error(tag.line, "not a PolyData file (<VTKFile type=\"" + (type == a.end() ? "" : type->second) + "\">)");
  if (const auto it = a.find("byte_order"); it != a.end())
  {
    if (it->second != "LittleEndian" && it->second != "BigEndian")
      return error(tag.line, "unknown byte_order '" + it->second + "' (LittleEndian or BigEndian)");
    bigEndian_ = it->second == "BigEndian";
  }
  if (const auto it = a.find("header_type"); it != a.end())
  {
    if (it->second != "UInt32" && it->second != "UInt64")
      return error(tag.line, "unknown header_type '" + it->second + "' (UInt32 or UInt64)");
    headerSize_ = it->second == "UInt64" ? 8 : 4;
  }
  if (const auto it = a.find("compressor"); it != a.end() && !it->second.empty())
  {
    compressor_ = it->second;
    if (it->second == "vtkZLibDataCompressor" || it->second == "vtkLZ4DataCompressor")
      ratio_ = 1032;
    else if (it->second == "vtkLZMADataCompressor")
      ratio_ = 65536;
    else
      return error(tag.line, "unknown compressor '" + it->second + "'");
  }
  return {};
}

Count VTPChecker::readHeaderInt(const std::string& bytes, std::size_t at) const
{
  Count value = 0;
  for (std::size_t b = 0; b < headerSize_; ++b)
  {
    const Count byte = static_cast<unsigned char>(bytes[at + b]);
    value |= byte << (8 * (bigEndian_ ? headerSize_ - 1 - b : b));
  }
  return value;
}

// Checks the block header at `at` in `data` and the bytes after it: they must
// hold `need` bytes.
Status VTPChecker::checkBlocks(
  const std::string& where, const std::string& data, std::size_t at, Count need, BlockData& block)
{
  block = BlockData{};
  const Count present = data.size() - std::min<std::size_t>(at, data.size());
  if (present < headerSize_)
    return Status::error(where + ": no room for its " + std::to_string(headerSize_) + "-byte header");
  if (ratio_ == 0)
  {
    const Count bytes = readHeaderInt(data, at);
    if (bytes > present - headerSize_)
      return Status::error(where + ": its header claims " + std::to_string(bytes) + " bytes but " +
        std::to_string(present - headerSize_) + " follow");
    if (need > bytes)
      return Status::error(where + ": needs " + std::to_string(need) + " bytes but its data has " +
        std::to_string(bytes));
    block.bytes = bytes;
    block.at = at + headerSize_;
    return {};
  }
  block.compressed = true;
  if (present < 3 * headerSize_)
    return Status::error(where + ": no room for its compression header");
  const Count blocks = readHeaderInt(data, at);
  const Count blockSize = readHeaderInt(data, at + headerSize_);
  const Count lastSize = readHeaderInt(data, at + 2 * headerSize_);
  if (blocks > (present - 3 * headerSize_) / headerSize_)
    return Status::error(where + ": its header claims " + std::to_string(blocks) +
      " compressed blocks, more than the data can describe");
  Count compressed = 0;
  block.compressedSizes.resize(static_cast<std::size_t>(blocks));
  for (Count b = 0; b < blocks; ++b)
  {
    block.compressedSizes[b] = readHeaderInt(data, at + (3 + b) * headerSize_);
    compressed = sum(compressed, block.compressedSizes[b]);
  }
  const Count headerBytes = (3 + blocks) * headerSize_;
  if (compressed > present - headerBytes)
    return Status::error(where + ": its header claims " + std::to_string(compressed) + " compressed bytes but " +
      std::to_string(present - headerBytes) + " follow");
  const Count uncompressed =
    blocks == 0 ? 0 : sum(product(blocks - 1, blockSize), lastSize == 0 ? blockSize : lastSize);
  if (uncompressed > product(ratio_, compressed))
    return Status::error(where + ": its header claims " + std::to_string(uncompressed) + " bytes from " +
      std::to_string(compressed) + " compressed ones, more than the compressor can produce");
  if (need > uncompressed)
    return Status::error(where + ": needs " + std::to_string(need) + " bytes but its data has " +
      std::to_string(uncompressed));
  block.bytes = uncompressed;
  block.at = at + static_cast<std::size_t>(headerBytes);
  block.blockSize = blockSize;
  block.lastSize = lastSize == 0 ? blockSize : lastSize;
  return {};
}

// Block `index` of a compressed array, decompressed into `raw`.
Status VTPChecker::decompressBlock(
  const ArrayInfo& array, const std::string& data, const BlockData& block, Count index, std::string& raw) const
{
  std::size_t at = block.at;
  for (Count b = 0; b < index; ++b)
    at += static_cast<std::size_t>(block.compressedSizes[b]);
  const Count size = index + 1 == block.compressedSizes.size() ? block.lastSize : block.blockSize;
  raw.assign(static_cast<std::size_t>(size), '\0');
  const auto* in = reinterpret_cast<const unsigned char*>(data.data() + at);
  if (!decompress_(compressor_, in, static_cast<std::size_t>(block.compressedSizes[index]),
        reinterpret_cast<unsigned char*>(&raw[0]), raw.size()))
    return Status::error(array.what + ": its compressed block " + std::to_string(index) + " does not decompress to " +
      std::to_string(size) + " bytes");
  return {};
}

// The checks of values (string counts, last offsets) on compressed data:
// a string array's blocks one after another, an offsets array's last value
// from its last blocks.
Status VTPChecker::checkCompressedArray(const ArrayInfo& array, const std::string& data, const BlockData& block)
{
  const Count blocks = block.compressedSizes.size();
  std::string raw;
  if (array.type == "String")
  {
    Count strings = 0;
    for (Count b = 0; b < blocks; ++b)
    {
      if (Status s = decompressBlock(array, data, block, b, raw); !s.ok())
        return s;
      strings += static_cast<Count>(std::count(raw.begin(), raw.end(), '\0'));
    }
    return checkStringCount(array, strings);
  }
  CellArrays* found = noteCellArray(array, block.bytes);
  if (!found)
    return {};
  CellArrays& cells = *found;
  const Count size = static_cast<Count>(array.size);
  if (array.isOffsets && block.bytes >= size && blocks > 0)
  {
    // The last value's bytes, which can start in the block before the last.
    std::string tail;
    for (Count b = blocks; b-- > 0 && tail.size() < size;)
    {
      if (Status s = decompressBlock(array, data, block, b, raw); !s.ok())
        return s;
      tail = raw + tail;
    }
    if (tail.size() < size)
      return Status::error(array.what + ": its compressed blocks hold less than one value");
    cells.haveLastOffset = true;
    cells.lastOffset = readValue(tail, tail.size() - array.size, array.type);
    cells.where = array.what;
  }
  return {};
}

// The cell arrays `array` belongs to (null if none, or if its values have
// no size), with its value count noted if it is their connectivity.
CellArrays* VTPChecker::noteCellArray(const ArrayInfo& array, Count bytes)
{
  if (array.cells.empty() || array.size == 0)
    return nullptr;
  CellArrays& cells = cellArrays_[array.cells];
  if (array.isConnectivity)
  {
    cells.haveConnectivity = true;
    cells.connectivity = bytes / static_cast<Count>(array.size);
  }
  return &cells;
}

// An integer value of `type` at `at` in the file's byte order (floats: 0).
Count VTPChecker::readValue(const std::string& bytes, std::size_t at, const std::string& type) const
{
  const int size = valueSize(type);
  Count value = 0;
  for (int b = 0; b < size; ++b)
  {
    const Count byte = static_cast<unsigned char>(bytes[at + b]);
    value |= byte << (8 * (bigEndian_ ? size - 1 - b : b));
  }
  const bool isSigned = type[0] == 'I';
  if (isSigned && size < 8 && (value >> (8 * size - 1)) != 0)
    return kHuge; // negative: no connectivity holds it
  if (isSigned && size == 8 && (value >> 63) != 0)
    return kHuge;
  return type[0] == 'F' ? 0 : value;
}

// VTK stores the strings it splits off into an array of the declared size:
// more strings than that writes past its end.
Status VTPChecker::checkStringCount(const ArrayInfo& array, Count strings) const
{
  if (strings != array.values)
    return Status::error(array.what + " holds " + std::to_string(strings) + " strings but declares " +
      std::to_string(array.values));
  return {};
}

Status VTPChecker::checkBinaryArray(const ArrayInfo& array, const std::string& data, std::size_t at)
{
  BlockData block;
  if (Status s = checkBlocks(array.what, data, at, array.need, block); !s.ok())
    return s;
  if (block.compressed)
    return decompress_ ? checkCompressedArray(array, data, block) : Status{}; // else its values cannot be seen
  if (array.type == "String")
  {
    const auto begin = data.begin() + static_cast<std::ptrdiff_t>(block.at);
    return checkStringCount(array, static_cast<Count>(std::count(begin, begin + static_cast<std::ptrdiff_t>(block.bytes), '\0')));
  }
  CellArrays* found = noteCellArray(array, block.bytes);
  if (!found)
    return {};
  CellArrays& cells = *found;
  if (array.isOffsets && block.bytes >= static_cast<Count>(array.size))
  {
    cells.haveLastOffset = true;
    cells.lastOffset = readValue(data, block.at + static_cast<std::size_t>(block.bytes) - array.size, array.type);
    cells.where = array.what;
  }
  return {};
}

Status VTPChecker::checkCellArrays() const
{
  for (const auto& [key, cells] : cellArrays_)
  {
    if (cells.haveLastOffset && cells.lastOffset > 0 && (!cells.haveConnectivity || cells.lastOffset > cells.connectivity))
      return Status::error(cells.where + ": its last offset, " +
        (cells.lastOffset == kHuge ? std::string("negative") : std::to_string(cells.lastOffset)) +
        ", is beyond the " + std::to_string(cells.haveConnectivity ? cells.connectivity : 0) +
        " values of the connectivity");
  }
  return {};
}

Status VTPChecker::checkArray(const Tag& tag, const std::string& parent, const std::string& content)
{
  const auto& a = tag.attributes;
  const auto name = a.find("Name");
  const std::string what = fileLine(path_, tag.line) + tag.name +
    (name == a.end() ? std::string() : " '" + name->second + "'");
  const auto type = a.find("type");
  if (type == a.end())
    return Status::error(what + " has no type");
  const int size = valueSize(type->second);
  if (size < 0)
    return Status::error(what + " has type '" + type->second +
      "', which VTK does not know (Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64, "
      "String, Bit)");
  Count components = 1;
  if (const auto it = a.find("NumberOfComponents"); it != a.end())
  {
    if (!parseCount(it->second, components) || components == 0)
      return Status::error(what + ": NumberOfComponents '" + it->second + "' is not a positive integer");
    // VTK reads it as an int; a cell array's connectivity and offsets have
    // one (VTK 9.2 spins on a huge count there).
    if (components > 2147483647)
      return Status::error(what + ": NumberOfComponents '" + it->second + "' is larger than VTK reads (2147483647)");
    if ((parent == "Verts" || parent == "Lines" || parent == "Strips" || parent == "Polys") && components != 1)
      return Status::error(what + ": NumberOfComponents is " + it->second + ", but a cell array has 1");
  }
  // The tuples VTK may allocate: the array's own count and the piece's.
  Count tuples = 0;
  if (const auto it = a.find("NumberOfTuples"); it != a.end())
  {
    if (!parseCount(it->second, tuples))
      return Status::error(what + ": NumberOfTuples '" + it->second + "' is not an integer");
  }
  const std::string arrayName = name == a.end() ? std::string() : name->second;
  if (parent == "Points" || parent == "PointData")
    tuples = std::max(tuples, piece_.points);
  else if (parent == "CellData")
    tuples = std::max(tuples, piece_.cells());
  else if (arrayName == "offsets")
  {
    const Count cells = parent == "Verts" ? piece_.verts
      : parent == "Lines"                 ? piece_.lines
      : parent == "Strips"                ? piece_.strips
      : parent == "Polys"                 ? piece_.polys
                                          : 0;
    tuples = std::max(tuples, cells);
  }
  ArrayInfo array;
  array.what = what;
  array.type = type->second;
  array.size = size;
  array.values = product(tuples, components);
  const Count values = array.values;
  array.need = array.type == "String" ? values
    : array.type == "Bit"             ? values / 8 + (values % 8 ? 1 : 0)
                                      : product(values, static_cast<Count>(size));
  if (parent == "Verts" || parent == "Lines" || parent == "Strips" || parent == "Polys")
  {
    array.cells = std::to_string(pieces_) + "/" + parent;
    array.isOffsets = arrayName == "offsets";
    array.isConnectivity = arrayName == "connectivity";
  }
  const auto formatIt = a.find("format");
  const std::string format = formatIt == a.end() ? "ascii" : formatIt->second;
  if (format == "ascii")
  {
    Count words = 0, zeros = 0;
    std::string last;
    for (std::size_t i = 0; i < content.size();)
    {
      while (i < content.size() && isBlank(content[i]))
        ++i;
      if (i >= content.size())
        break;
      ++words;
      const std::size_t begin = i;
      while (i < content.size() && !isBlank(content[i]))
        ++i;
      last.assign(content, begin, i - begin);
      zeros += last == "0" ? 1 : 0;
    }
    if (words < values)
      return Status::error(what + " needs " + std::to_string(values) + " values (" + std::to_string(tuples) +
        " tuples of " + std::to_string(components) + ") but has " + std::to_string(words));
    if (array.type == "String")
      return checkStringCount(array, zeros);
    if (!array.cells.empty())
    {
      CellArrays& cells = cellArrays_[array.cells];
      if (array.isConnectivity)
      {
        cells.haveConnectivity = true;
        cells.connectivity = words;
      }
      Count lastOffset = 0;
      if (array.isOffsets && words > 0)
      {
        cells.haveLastOffset = true;
        cells.lastOffset = parseCount(last, lastOffset) ? lastOffset : kHuge;
        cells.where = what;
      }
    }
    return {};
  }
  if (format == "binary")
  {
    std::string decoded;
    if (!decodeBase64(content, 0, content.size(), decoded))
      return Status::error(what + ": its binary data is not base64");
    return checkBinaryArray(array, decoded, 0);
  }
  if (format == "appended")
  {
    const auto offset = a.find("offset");
    if (offset == a.end() || !parseCount(offset->second, array.offset))
      return Status::error(what + ": an appended array needs an integer offset");
    appended_.push_back(array);
    return {};
  }
  return Status::error(what + " has format '" + format + "' (ascii, binary or appended)");
}

Status VTPChecker::checkAppended(const Tag& tag)
{
  const auto encodingIt = tag.attributes.find("encoding");
  const std::string encoding = encodingIt == tag.attributes.end() ? "raw" : encodingIt->second;
  if (encoding != "raw" && encoding != "base64")
    return error(tag.line, "unknown AppendedData encoding '" + encoding + "' (raw or base64)");
  // VTK's parser takes the first character after blanks for the '_' and,
  // when it is not, reads block headers from the wrong place.
  std::size_t underscore = tag.end;
  while (underscore < text_.size() && isBlank(text_[underscore]))
    ++underscore;
  if (underscore >= text_.size() || text_[underscore] != '_')
    return error(lineAt(underscore), "AppendedData does not start with '_' (only blanks may come before it)");
  const std::size_t begin = underscore + 1;
  if (encoding == "raw")
  {
    // Raw bytes can hold anything, '<' included: the section ends at the
    // last closing tag.
    const std::size_t close = text_.rfind("</AppendedData>");
    const std::size_t end = close == std::string::npos || close < begin ? text_.size() : close;
    const std::string data = text_.substr(begin, end - begin);
    for (const ArrayInfo& array : appended_)
    {
      if (array.offset >= data.size())
        return Status::error(array.what + ": offset " + std::to_string(array.offset) +
          " is beyond the appended data (" + std::to_string(data.size()) + " bytes)");
      if (Status s = checkBinaryArray(array, data, static_cast<std::size_t>(array.offset)); !s.ok())
        return s;
    }
    return checkCellArrays();
  }
  const std::size_t end = std::min(text_.find('<', begin), text_.size());
  for (const ArrayInfo& array : appended_)
  {
    if (array.offset >= end - begin)
      return Status::error(array.what + ": offset " + std::to_string(array.offset) +
        " is beyond the appended data (" + std::to_string(end - begin) + " characters)");
    std::string decoded;
    if (!decodeBase64(text_, begin + static_cast<std::size_t>(array.offset), end, decoded))
      return Status::error(array.what + ": the appended data at its offset is not base64");
    if (Status s = checkBinaryArray(array, decoded, 0); !s.ok())
      return s;
  }
  return checkCellArrays();
}

Status VTPChecker::check()
{
  Tag tag;
  std::string problem;
  if (!nextTag(tag, problem))
    return error(lineAt(pos_), problem.empty() ? "no XML element: not a VTK XML file" : problem);
  if (Status s = checkRoot(tag); !s.ok())
    return s;
  if (tag.empty)
    return error(tag.line, "an empty <VTKFile/>");
  std::vector<Tag> open{ tag };
  std::string content; // character data directly inside the open array
  std::size_t contentFrom = tag.end;
  while (true)
  {
    if (!nextTag(tag, problem))
    {
      if (!problem.empty())
        return error(lineAt(pos_), problem);
      if (!open.empty())
        return error(lineAt(text_.size()), "the file ends inside <" + open.back().name + "> (line " +
          std::to_string(open.back().line) + ")");
      break;
    }
    if (!open.empty() && isArray(open.back().name))
      content.append(text_, contentFrom, tag.begin - contentFrom);
    if (tag.closing)
    {
      if (open.empty() || open.back().name != tag.name)
        return error(tag.line, "</" + tag.name + "> closes " +
          (open.empty() ? std::string("nothing") : "<" + open.back().name + "> (line " +
            std::to_string(open.back().line) + ")"));
      if (isArray(tag.name))
      {
        const Tag array = open.back();
        const std::string parent = open.size() >= 2 ? open[open.size() - 2].name : std::string();
        if (Status s = checkArray(array, parent, content); !s.ok())
          return s;
        content.clear();
      }
      open.pop_back();
      contentFrom = tag.end;
      if (open.empty())
        break;
      continue;
    }
    if (open.empty())
      return error(tag.line, "<" + tag.name + "> after the end of <VTKFile>");
    if (tag.name == "Piece")
    {
      ++pieces_;
      piece_ = PieceCounts{};
      const std::pair<const char*, Count*> counts[] = { { "NumberOfPoints", &piece_.points },
        { "NumberOfVerts", &piece_.verts }, { "NumberOfLines", &piece_.lines },
        { "NumberOfStrips", &piece_.strips }, { "NumberOfPolys", &piece_.polys } };
      for (const auto& [attribute, value] : counts)
      {
        const auto it = tag.attributes.find(attribute);
        if (it != tag.attributes.end() && !parseCount(it->second, *value))
          return error(tag.line, std::string(attribute) + " '" + it->second + "' is not an integer");
      }
    }
    if (tag.name == "AppendedData")
      return checkAppended(tag);
    if (isArray(tag.name) && tag.empty)
    {
      const std::string parent = open.back().name;
      if (Status s = checkArray(tag, parent, std::string()); !s.ok())
        return s;
    }
    contentFrom = tag.end;
    if (isArray(tag.name))
      content.clear();
    if (!tag.empty)
      open.push_back(tag);
  }
  if (!appended_.empty())
    return Status::error(appended_.front().what + ": appended, but the file has no AppendedData");
  return checkCellArrays();
}

} // namespace

Status checkVTPFile(const std::string& path, const VTPDecompressor& decompress)
{
  std::string text;
  if (Status s = readFileBytes(path, text); !s.ok())
    return s;
  return VTPChecker(path, text, decompress).check();
}

} // namespace cmp
