#include <cmp/io/MeshFile.h>

#include <cmp/io/TextParsing.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>

namespace cmp
{
namespace
{

enum class PlyType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64
};

bool parsePlyType(const std::string& name, PlyType& type)
{
  static const struct
  {
    const char* name;
    PlyType type;
  } names[] = { { "char", PlyType::Int8 }, { "int8", PlyType::Int8 }, { "uchar", PlyType::UInt8 },
    { "uint8", PlyType::UInt8 }, { "short", PlyType::Int16 }, { "int16", PlyType::Int16 },
    { "ushort", PlyType::UInt16 }, { "uint16", PlyType::UInt16 }, { "int", PlyType::Int32 },
    { "int32", PlyType::Int32 }, { "uint", PlyType::UInt32 }, { "uint32", PlyType::UInt32 },
    { "float", PlyType::Float32 }, { "float32", PlyType::Float32 }, { "double", PlyType::Float64 },
    { "float64", PlyType::Float64 } };
  for (const auto& entry : names)
  {
    if (name == entry.name)
    {
      type = entry.type;
      return true;
    }
  }
  return false;
}

std::size_t typeSize(PlyType type)
{
  switch (type)
  {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 8;
}

bool isIntegerType(PlyType type)
{
  return type != PlyType::Float32 && type != PlyType::Float64;
}

// The range of an integer type (exact in a double).
void integerRange(PlyType type, double& lowest, double& highest)
{
  switch (type)
  {
    case PlyType::Int8:
      lowest = -128, highest = 127;
      return;
    case PlyType::UInt8:
      lowest = 0, highest = 255;
      return;
    case PlyType::Int16:
      lowest = -32768, highest = 32767;
      return;
    case PlyType::UInt16:
      lowest = 0, highest = 65535;
      return;
    case PlyType::Int32:
      lowest = -2147483648.0, highest = 2147483647.0;
      return;
    default:
      lowest = 0, highest = 4294967295.0;
      return;
  }
}

struct PlyProperty
{
  std::string name;
  bool isList = false;
  PlyType countType = PlyType::UInt8; // lists only
  PlyType type = PlyType::Float32;    // the scalar's or the list items' type
};

struct PlyElement
{
  std::string name;
  std::uint64_t count = 0;
  std::string countText; // as written, for messages
  int line = 0;          // header line that declares it
  std::vector<PlyProperty> properties;
};

enum class PlyFormat
{
  Ascii,
  LittleEndian,
  BigEndian
};

// What an element's records hold for the mesh: which properties are the
// coordinates (vertex) or the index list (face); -1 when not that element.
struct Roles
{
  int x = -1, y = -1, z = -1, indices = -1;
  // Per property, where its values are kept in pointProperties (vertex) or
  // triangleProperties (face); -1 when skipped.
  std::vector<int> kept;
};

// "point", "face" or "'name' element", for messages.
std::string recordName(const PlyElement& element)
{
  if (element.name == "vertex")
    return "point";
  if (element.name == "face")
    return "face";
  return "'" + element.name + "' element";
}

std::string plural(const PlyElement& element)
{
  if (element.name == "vertex")
    return "points";
  if (element.name == "face")
    return "faces";
  return "'" + element.name + "' elements";
}

std::vector<std::string> splitWords(const std::string& line)
{
  std::vector<std::string> words;
  std::size_t p = 0;
  while (true)
  {
    p = line.find_first_not_of(" \t\r\v\f", p);
    if (p == std::string::npos)
      break;
    const std::size_t e = std::min(line.find_first_of(" \t\r\v\f", p), line.size());
    words.push_back(line.substr(p, e - p));
    p = e;
  }
  return words;
}

// Unsigned decimal without sign or blanks; saturates at 2^64 - 1.
bool parseCount(const std::string& word, std::uint64_t& count)
{
  if (word.empty() || word.find_first_not_of("0123456789") != std::string::npos)
    return false;
  count = 0;
  for (char c : word)
  {
    const std::uint64_t digit = static_cast<std::uint64_t>(c - '0');
    if (count > (std::numeric_limits<std::uint64_t>::max() - digit) / 10)
    {
      count = std::numeric_limits<std::uint64_t>::max();
      return true;
    }
    count = count * 10 + digit;
  }
  return true;
}

std::uint64_t saturatingProduct(std::uint64_t a, std::uint64_t b)
{
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a)
    return std::numeric_limits<std::uint64_t>::max();
  return a * b;
}

class PlyParser
{
public:
  PlyParser(const std::string& path, const std::string& bytes)
    : path_(path)
    , bytes_(bytes)
  {
  }

  Status read(MeshFileData& out);

private:
  Status parseHeader();
  Status checkElements();
  Status checkSizes() const;
  Status readAscii(MeshFileData& out);
  Status readBinary(MeshFileData& out);
  Status takeFace(
    const std::vector<double>& polygon, std::uint64_t face, const std::string& where, MeshFileData& out) const;
  Status checkCountsFitInt();
  Status takeRecord(const Roles& roles, const double* xyz, const std::vector<double>& polygon,
    const std::vector<double>& values, std::uint64_t record, const std::string& where, MeshFileData& out) const;
  bool nextHeaderLine(std::string& line);
  Status headerError(const std::string& what) const { return Status::error(fileLine(path_, line_) + what); }
  Status byteError(std::size_t offset, const std::string& what) const
  {
    return Status::error(path_ + ": byte " + std::to_string(offset) + ": " + what);
  }
  bool readBinaryValue(PlyType type, std::size_t& pos, double& value) const;

  const std::string& path_;
  const std::string& bytes_;
  std::size_t pos_ = 0; // next byte to read
  int line_ = 0;        // last line read (header, then ASCII body)
  PlyFormat format_ = PlyFormat::Ascii;
  std::vector<PlyElement> elements_;
  std::vector<Roles> roles_;
  int vertexCount_ = 0;
};

bool PlyParser::nextHeaderLine(std::string& line)
{
  if (pos_ >= bytes_.size())
    return false;
  const std::size_t end = std::min(bytes_.find('\n', pos_), bytes_.size());
  line.assign(bytes_, pos_, end - pos_);
  if (!line.empty() && line.back() == '\r')
    line.pop_back();
  pos_ = std::min(end + 1, bytes_.size());
  ++line_;
  return true;
}

Status PlyParser::parseHeader()
{
  std::string line;
  if (!nextHeaderLine(line) || line != "ply")
    return Status::error(fileLine(path_, 1) + "not a PLY file (the first line must be 'ply')");
  bool haveFormat = false;
  while (true)
  {
    if (!nextHeaderLine(line))
      return headerError("the file ends in the header (no 'end_header' line)");
    const std::vector<std::string> words = splitWords(line);
    if (words.empty())
      continue;
    const std::string& keyword = words[0];
    if (keyword == "comment" || keyword == "obj_info")
      continue;
    if (keyword == "end_header")
    {
      if (words.size() != 1)
        return headerError("'end_header' takes nothing after it");
      if (!haveFormat)
        return headerError("no 'format' line before 'end_header'");
      return {};
    }
    if (keyword == "format")
    {
      if (haveFormat)
        return headerError("a second 'format' line");
      if (words.size() != 3)
        return headerError("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (words[1] == "ascii")
        format_ = PlyFormat::Ascii;
      else if (words[1] == "binary_little_endian")
        format_ = PlyFormat::LittleEndian;
      else if (words[1] == "binary_big_endian")
        format_ = PlyFormat::BigEndian;
      else
        return headerError("unknown format '" + words[1] + "' (ascii, binary_little_endian or binary_big_endian)");
      if (words[2] != "1.0")
        return headerError("unsupported PLY version '" + words[2] + "' (1.0 is read)");
      haveFormat = true;
    }
    else if (keyword == "element")
    {
      if (!haveFormat)
        return headerError("'element' before the 'format' line");
      PlyElement element;
      if (words.size() != 3 || !parseCount(words[2], element.count))
        return headerError("expected 'element NAME COUNT' with a count of zero or more");
      element.name = words[1];
      element.countText = words[2];
      element.line = line_;
      for (const PlyElement& other : elements_)
      {
        if (other.name == element.name)
          return headerError("a second element '" + element.name + "' (the first is on line " +
            std::to_string(other.line) + ")");
      }
      elements_.push_back(element);
    }
    else if (keyword == "property")
    {
      if (elements_.empty())
        return headerError("'property' before any 'element'");
      PlyProperty property;
      if (words.size() == 5 && words[1] == "list")
      {
        property.isList = true;
        if (!parsePlyType(words[2], property.countType) || !parsePlyType(words[3], property.type))
          return headerError("unknown type in 'property list " + words[2] + " " + words[3] + "'");
        if (!isIntegerType(property.countType))
          return headerError("a list's count type must be an integer type, not '" + words[2] + "'");
        property.name = words[4];
      }
      else if (words.size() == 3 && words[1] != "list")
      {
        if (!parsePlyType(words[1], property.type))
          return headerError("unknown property type '" + words[1] + "'");
        property.name = words[2];
      }
      else
        return headerError("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      for (const PlyProperty& other : elements_.back().properties)
      {
        if (other.name == property.name)
          return headerError("a second property '" + property.name + "' in element '" + elements_.back().name + "'");
      }
      elements_.back().properties.push_back(property);
    }
    else
      return headerError("unknown header line '" + keyword + "'");
  }
}

Status PlyParser::checkElements()
{
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  roles_.assign(elements_.size(), Roles{});
  for (std::size_t e = 0; e < elements_.size(); ++e)
  {
    const PlyElement& element = elements_[e];
    if (element.properties.empty() && element.count > 0)
      return Status::error(fileLine(path_, element.line) + "element '" + element.name + "' has no properties");
    Roles& roles = roles_[e];
    for (std::size_t k = 0; k < element.properties.size(); ++k)
    {
      const PlyProperty& property = element.properties[k];
      const int index = static_cast<int>(k);
      if (element.name == "vertex" && !property.isList)
      {
        if (property.name == "x")
          roles.x = index;
        else if (property.name == "y")
          roles.y = index;
        else if (property.name == "z")
          roles.z = index;
      }
      if (element.name == "face" && property.isList &&
        (property.name == "vertex_indices" || property.name == "vertex_index"))
      {
        if (roles.indices >= 0)
          return Status::error(fileLine(path_, element.line) + "the face element has both 'vertex_indices' and 'vertex_index'");
        if (!isIntegerType(property.type))
          return Status::error(fileLine(path_, element.line) + "face indices must have an integer type");
        roles.indices = index;
      }
    }
    if (element.name == "vertex")
    {
      vertex = &element;
      if (roles.x < 0 || roles.y < 0 || roles.z < 0)
        return Status::error(fileLine(path_, element.line) + "the vertex element needs the scalar properties x, y and z");
    }
    if (element.name == "face")
    {
      face = &element;
      if (roles.indices < 0)
        return Status::error(
          fileLine(path_, element.line) + "the face element has no list property 'vertex_indices' or 'vertex_index'");
    }
  }
  if (!vertex)
    return Status::error(fileLine(path_, line_) + "no 'vertex' element in the header");
  if (!face)
    return Status::error(fileLine(path_, line_) + "no 'face' element in the header: not a surface");
  return {};
}

// Point ids and triangle corners are ints.
Status PlyParser::checkCountsFitInt()
{
  const std::uint64_t most = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
  for (std::size_t e = 0; e < elements_.size(); ++e)
  {
    const PlyElement& element = elements_[e];
    if ((roles_[e].x >= 0 || roles_[e].indices >= 0) && element.count > most)
      return Status::error(fileLine(path_, element.line) + "more than " + std::to_string(most) + " " +
        plural(element) + " are not supported");
    if (roles_[e].x >= 0)
      vertexCount_ = static_cast<int>(element.count);
  }
  return {};
}

// Every record takes a least number of bytes (binary: its scalars and list
// counts, and three indices per face; ASCII: one character and one blank or
// line break per value); the counts must fit in the bytes after the header.
Status PlyParser::checkSizes() const
{
  const bool ascii = format_ == PlyFormat::Ascii;
  // An ASCII file's last line may lack its line break.
  std::uint64_t room = bytes_.size() - pos_ + (ascii ? 1 : 0);
  for (std::size_t e = 0; e < elements_.size(); ++e)
  {
    const PlyElement& element = elements_[e];
    std::uint64_t least = 0;
    for (std::size_t k = 0; k < element.properties.size(); ++k)
    {
      const PlyProperty& property = element.properties[k];
      const std::uint64_t items = static_cast<int>(k) == roles_[e].indices ? 3 : 0;
      if (ascii)
        least += 2 * (1 + items);
      else
        least += property.isList ? typeSize(property.countType) + items * typeSize(property.type)
                                 : typeSize(property.type);
    }
    const std::uint64_t need = saturatingProduct(element.count, least);
    if (need > room)
      return Status::error(fileLine(path_, element.line) + "the header claims " + element.countText + " " +
        plural(element) + " but the file has room for at most " + std::to_string(room / least));
    room -= need;
  }
  return {};
}

Status PlyParser::takeFace(
  const std::vector<double>& polygon, std::uint64_t face, const std::string& where, MeshFileData& out) const
{
  if (polygon.size() < 3)
    return Status::error(where + "face " + std::to_string(face) + " has " +
      std::to_string(polygon.size()) + " vertices; a face needs at least three");
  for (double v : polygon)
  {
    if (!(v >= 0 && v < vertexCount_))
      return Status::error(where + "vertex index " + std::to_string(static_cast<long long>(v)) +
        " out of range (the file has " + std::to_string(vertexCount_) + " points)");
  }
  if (out.mesh.triangles.size() + polygon.size() - 2 > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    return Status::error(where + "more triangles than are supported");
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
    out.mesh.triangles.push_back(
      { static_cast<int>(polygon[0]), static_cast<int>(polygon[k]), static_cast<int>(polygon[k + 1]) });
  return {};
}

Status PlyParser::takeRecord(const Roles& roles, const double* xyz, const std::vector<double>& polygon,
  const std::vector<double>& values, std::uint64_t record, const std::string& where, MeshFileData& out) const
{
  const std::size_t before = out.mesh.triangles.size();
  if (roles.x >= 0)
    out.mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
  else if (roles.indices >= 0)
  {
    if (Status s = takeFace(polygon, record, where, out); !s.ok())
      return s;
  }
  else
    return {};
  // A point's values once, a polygon's once per triangle.
  const std::size_t copies = roles.x >= 0 ? 1 : out.mesh.triangles.size() - before;
  std::vector<MeshFileProperty>& kept = roles.x >= 0 ? out.pointProperties : out.triangleProperties;
  for (std::size_t k = 0; k < roles.kept.size(); ++k)
  {
    if (roles.kept[k] >= 0)
      kept[roles.kept[k]].values.insert(kept[roles.kept[k]].values.end(), copies, values[roles.kept[k]]);
  }
  return {};
}

// Parses one ASCII value of `type`: integers must be integers within the
// type's range; float values are rounded to float as the file declares.
bool parseAsciiValue(const std::string& word, PlyType type, double& value)
{
  const char* begin = word.c_str();
  char* end = nullptr;
  errno = 0;
  if (isIntegerType(type))
  {
    const long long v = std::strtoll(begin, &end, 10);
    if (end == begin || *end != '\0' || errno == ERANGE)
      return false;
    double lowest, highest;
    integerRange(type, lowest, highest);
    value = static_cast<double>(v);
    return value >= lowest && value <= highest;
  }
  const double v = std::strtod(begin, &end);
  if (end == begin || *end != '\0')
    return false;
  value = type == PlyType::Float32 ? static_cast<double>(static_cast<float>(v)) : v;
  return true;
}

std::string typeName(PlyType type)
{
  static const char* names[] = { "char", "uchar", "short", "ushort", "int", "uint", "float", "double" };
  return names[static_cast<int>(type)];
}

Status PlyParser::readAscii(MeshFileData& out)
{
  std::string line;
  std::vector<double> polygon;
  for (std::size_t e = 0; e < elements_.size(); ++e)
  {
    const PlyElement& element = elements_[e];
    const Roles& roles = roles_[e];
    std::vector<double> recordValues(roles.kept.size());
    for (std::uint64_t r = 0; r < element.count; ++r)
    {
      std::vector<std::string> words;
      while (words.empty())
      {
        if (!nextHeaderLine(line))
          return Status::error(fileLine(path_, line_) + "the file ends after " + std::to_string(r) + " of the " +
            element.countText + " " + plural(element) + " the header (line " + std::to_string(element.line) +
            ") claims");
        words = splitWords(line);
      }
      const std::string where = fileLine(path_, line_);
      const std::string what = recordName(element) + " " + std::to_string(r);
      std::size_t w = 0;
      double xyz[3] = { 0, 0, 0 };
      for (std::size_t k = 0; k < element.properties.size(); ++k)
      {
        const PlyProperty& property = element.properties[k];
        const int index = static_cast<int>(k);
        std::size_t items = 1;
        double value = 0;
        if (property.isList)
        {
          if (w >= words.size())
            return Status::error(where + what + " has " + std::to_string(words.size()) +
              " values, too few for its properties (list '" + property.name + "' has no count)");
          if (!parseAsciiValue(words[w], property.countType, value) || value < 0)
            return Status::error(where + what + ": list count '" + words[w] + "' is not a " +
              typeName(property.countType) + " of zero or more");
          ++w;
          items = static_cast<std::size_t>(value);
          if (items > words.size() - w)
            return Status::error(where + what + ": list '" + property.name + "' announces " + std::to_string(items) +
              " values but the line has " + std::to_string(words.size() - w) + " left");
          if (index == roles.indices)
            polygon.clear();
        }
        for (std::size_t i = 0; i < items; ++i, ++w)
        {
          if (w >= words.size())
            return Status::error(where + what + " has " + std::to_string(words.size()) +
              " values, too few for its properties ('" + property.name + "' is missing)");
          if (!parseAsciiValue(words[w], property.type, value))
            return Status::error(where + what + ": '" + words[w] + "' is not a " + typeName(property.type) +
              " (property '" + property.name + "')");
          if (index == roles.x)
            xyz[0] = value;
          else if (index == roles.y)
            xyz[1] = value;
          else if (index == roles.z)
            xyz[2] = value;
          else if (index == roles.indices)
            polygon.push_back(value);
          else if (roles.kept[k] >= 0)
            recordValues[roles.kept[k]] = value;
        }
      }
      if (w != words.size())
        return Status::error(where + what + " has " + std::to_string(words.size()) + " values; its properties take " +
          std::to_string(w));
      if (Status s = takeRecord(roles, xyz, polygon, recordValues, r, where, out); !s.ok())
        return s;
    }
  }
  while (nextHeaderLine(line))
  {
    if (!splitWords(line).empty())
      return Status::error(fileLine(path_, line_) + "data after the last element the header declares");
  }
  return {};
}

bool PlyParser::readBinaryValue(PlyType type, std::size_t& pos, double& value) const
{
  const std::size_t size = typeSize(type);
  if (bytes_.size() - pos < size)
    return false;
  std::uint64_t bits = 0;
  for (std::size_t b = 0; b < size; ++b)
  {
    const std::uint64_t byte = static_cast<unsigned char>(bytes_[pos + b]);
    const std::size_t shift = format_ == PlyFormat::LittleEndian ? b : size - 1 - b;
    bits |= byte << (8 * shift);
  }
  pos += size;
  switch (type)
  {
    case PlyType::Int8:
      value = static_cast<std::int8_t>(bits);
      break;
    case PlyType::UInt8:
      value = static_cast<std::uint8_t>(bits);
      break;
    case PlyType::Int16:
      value = static_cast<std::int16_t>(bits);
      break;
    case PlyType::UInt16:
      value = static_cast<std::uint16_t>(bits);
      break;
    case PlyType::Int32:
      value = static_cast<std::int32_t>(bits);
      break;
    case PlyType::UInt32:
      value = static_cast<std::uint32_t>(bits);
      break;
    case PlyType::Float32:
    {
      const std::uint32_t word = static_cast<std::uint32_t>(bits);
      float f;
      std::memcpy(&f, &word, sizeof(f));
      value = f;
      break;
    }
    case PlyType::Float64:
    {
      double d;
      std::memcpy(&d, &bits, sizeof(d));
      value = d;
      break;
    }
  }
  return true;
}

Status PlyParser::readBinary(MeshFileData& out)
{
  std::size_t pos = pos_;
  std::vector<double> polygon;
  for (std::size_t e = 0; e < elements_.size(); ++e)
  {
    const PlyElement& element = elements_[e];
    const Roles& roles = roles_[e];
    std::vector<double> recordValues(roles.kept.size());
    for (std::uint64_t r = 0; r < element.count; ++r)
    {
      const std::size_t start = pos;
      const auto ends = [&]()
      {
        return byteError(pos, "the file ends inside " + recordName(element) + " " + std::to_string(r) + " of the " +
          element.countText + " the header (line " + std::to_string(element.line) + ") claims");
      };
      double xyz[3] = { 0, 0, 0 };
      for (std::size_t k = 0; k < element.properties.size(); ++k)
      {
        const PlyProperty& property = element.properties[k];
        const int index = static_cast<int>(k);
        double value = 0;
        if (!property.isList)
        {
          if (!readBinaryValue(property.type, pos, value))
            return ends();
          if (index == roles.x)
            xyz[0] = value;
          else if (index == roles.y)
            xyz[1] = value;
          else if (index == roles.z)
            xyz[2] = value;
          else if (roles.kept[k] >= 0)
            recordValues[roles.kept[k]] = value;
          continue;
        }
        const std::size_t countAt = pos;
        if (!readBinaryValue(property.countType, pos, value))
          return ends();
        if (value < 0)
          return byteError(countAt, recordName(element) + " " + std::to_string(r) + ": list '" + property.name +
            "' has the negative count " + std::to_string(static_cast<long long>(value)));
        const std::uint64_t items = static_cast<std::uint64_t>(value);
        if (saturatingProduct(items, typeSize(property.type)) > bytes_.size() - pos)
          return byteError(countAt, recordName(element) + " " + std::to_string(r) + ": list '" + property.name +
            "' announces " + std::to_string(items) + " values but the file ends before them");
        if (index != roles.indices)
        {
          pos += static_cast<std::size_t>(items) * typeSize(property.type);
          continue;
        }
        polygon.clear();
        for (std::uint64_t i = 0; i < items; ++i)
        {
          readBinaryValue(property.type, pos, value);
          polygon.push_back(value);
        }
      }
      if (Status s = takeRecord(roles, xyz, polygon, recordValues, r, path_ + ": byte " + std::to_string(start) + ": ", out);
          !s.ok())
        return s;
    }
  }
  if (pos != bytes_.size())
    return byteError(pos, std::to_string(bytes_.size() - pos) + " bytes after the last element the header declares");
  return {};
}

Status PlyParser::read(MeshFileData& out)
{
  if (Status s = parseHeader(); !s.ok())
    return s;
  if (Status s = checkElements(); !s.ok())
    return s;
  if (Status s = checkSizes(); !s.ok())
    return s;
  if (Status s = checkCountsFitInt(); !s.ok())
    return s;
  for (std::size_t e = 0; e < elements_.size(); ++e)
  {
    const PlyElement& element = elements_[e];
    Roles& roles = roles_[e];
    const bool vertex = roles.x >= 0;
    const bool face = roles.indices >= 0;
    roles.kept.assign(element.properties.size(), -1);
    if (!vertex && !face)
      continue;
    const std::size_t count = static_cast<std::size_t>(element.count);
    std::vector<MeshFileProperty>& kept = vertex ? out.pointProperties : out.triangleProperties;
    for (std::size_t k = 0; k < element.properties.size(); ++k)
    {
      const int index = static_cast<int>(k);
      if (element.properties[k].isList || index == roles.x || index == roles.y || index == roles.z)
        continue;
      roles.kept[k] = static_cast<int>(kept.size());
      kept.push_back({ element.properties[k].name, {} });
      kept.back().values.reserve(count);
    }
    if (vertex)
      out.mesh.points.reserve(count);
    else
      out.mesh.triangles.reserve(count);
  }
  return format_ == PlyFormat::Ascii ? readAscii(out) : readBinary(out);
}

} // namespace

Status readPLY(const std::string& path, MeshFileData& out)
{
  out = MeshFileData{};
  std::string bytes;
  if (Status s = readFileBytes(path, bytes); !s.ok())
    return s;
  PlyParser parser(path, bytes);
  if (Status s = parser.read(out); !s.ok())
  {
    out = MeshFileData{};
    return s;
  }
  out.fileToMeshPoint.resize(out.mesh.points.size());
  std::iota(out.fileToMeshPoint.begin(), out.fileToMeshPoint.end(), 0);
  return {};
}

} // namespace cmp
