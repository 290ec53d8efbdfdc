#include "io/vtk_polydata.hpp"

#include <charconv>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <utility>

#include "io/vtk_zlib.hpp"

namespace bpm {
namespace {

template <class T>
VtkArray make_array(std::string name, VtkArray::Type type, int components,
                    std::span<const T> values) {
  VtkArray a{
      std::move(name), type, components, values.size() / static_cast<std::size_t>(components), {}};
  a.bytes.resize(values.size_bytes());
  if (!values.empty()) std::memcpy(a.bytes.data(), values.data(), values.size_bytes());
  return a;
}

std::span<const double> flat(std::span<const Vec3> v) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three packed doubles");
  return {reinterpret_cast<const double*>(v.data()), 3 * v.size()};
}

const char* type_name(VtkArray::Type t) {
  switch (t) {
    case VtkArray::Type::float64:
      return "Float64";
    case VtkArray::Type::int32:
      return "Int32";
    case VtkArray::Type::int64:
      return "Int64";
    case VtkArray::Type::string:
      return "String";
  }
  return "";
}

std::string xml_escaped(const std::string& text) {
  std::string s;
  for (const char c : text) {
    switch (c) {
      case '&':
        s += "&amp;";
        break;
      case '<':
        s += "&lt;";
        break;
      case '>':
        s += "&gt;";
        break;
      case '"':
        s += "&quot;";
        break;
      default:
        s += c;
    }
  }
  return s;
}

/// Appends the shortest text that reads back to the same value.
template <class T>
void append_number(std::string& s, T value) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, value).ptr;
  s.append(buf, end);
}

template <class T>
void append_values(std::string& s, const std::string& bytes, int per_line) {
  const std::size_t n = bytes.size() / sizeof(T);
  for (std::size_t i = 0; i < n; ++i) {
    T v;
    std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
    s += i % static_cast<std::size_t>(per_line) == 0 ? "\n          " : " ";
    append_number(s, v);
  }
  s += '\n';
}

/// Writes the XML of the arrays and collects the appended blocks.
class Writer {
 public:
  Writer(VtkEncoding encoding, int level) : encoding_(encoding), level_(level) {}

  void array(std::string& xml, const VtkArray& a, bool field) {
    const bool string = a.type == VtkArray::Type::string;
    xml += "        <";
    xml += string ? "Array" : "DataArray";
    xml += " type=\"" + std::string(type_name(a.type)) + "\" Name=\"" + xml_escaped(a.name) + "\"";
    if (!string) xml += " NumberOfComponents=\"" + std::to_string(a.components) + "\"";
    if (field) xml += " NumberOfTuples=\"" + std::to_string(a.tuples) + "\"";
    if (encoding_ == VtkEncoding::zlib) {
      xml += " format=\"appended\" offset=\"" + std::to_string(appended_.size()) + "\"/>\n";
      // Doubles of a DEM state have random mantissas that string matching does not shorten.
      appended_ += vtk_zlib_block(a.bytes, level_, a.type == VtkArray::Type::float64);
      return;
    }
    xml += " format=\"ascii\">";
    switch (a.type) {
      case VtkArray::Type::float64:
        append_values<double>(xml, a.bytes, a.components);
        break;
      case VtkArray::Type::int32:
        append_values<std::int32_t>(xml, a.bytes, a.components);
        break;
      case VtkArray::Type::int64:
        append_values<std::int64_t>(xml, a.bytes, a.components);
        break;
      case VtkArray::Type::string: {
        // VTK's ASCII strings: the character codes, each string ended by 0.
        for (std::size_t i = 0; i < a.bytes.size(); ++i) {
          xml += i == 0 ? "\n          " : " ";
          append_number(xml, static_cast<int>(static_cast<unsigned char>(a.bytes[i])));
        }
        xml += '\n';
        break;
      }
    }
    xml += string ? "        </Array>\n" : "        </DataArray>\n";
  }

  /// `tuples`: the count every array must have (points or cells); field data has its own.
  void section(std::string& xml, const char* tag, const VtkArrays& arrays,
               std::optional<std::size_t> tuples) {
    for (const VtkArray& a : arrays.arrays()) {
      if (tuples && a.tuples != *tuples)
        throw std::logic_error(std::string(tag) + " array " + a.name + " has " +
                               std::to_string(a.tuples) + " tuples, not " +
                               std::to_string(*tuples));
    }
    const bool field = !tuples;
    xml += std::string(field ? "    <" : "      <") + std::string(tag);
    if (!arrays.active_scalars().empty())
      xml += " Scalars=\"" + xml_escaped(arrays.active_scalars()) + "\"";
    if (!arrays.active_vectors().empty())
      xml += " Vectors=\"" + xml_escaped(arrays.active_vectors()) + "\"";
    xml += ">\n";
    for (const VtkArray& a : arrays.arrays()) array(xml, a, field);
    xml += std::string(field ? "    </" : "      </") + std::string(tag) + ">\n";
  }

  void cells(std::string& xml, const char* tag, const std::vector<std::int64_t>& connectivity,
             const std::vector<std::int64_t>& offsets) {
    if (offsets.empty()) return;
    xml += "      <" + std::string(tag) + ">\n";
    array(xml, make_array<std::int64_t>("connectivity", VtkArray::Type::int64, 1, connectivity),
          false);
    array(xml, make_array<std::int64_t>("offsets", VtkArray::Type::int64, 1, offsets), false);
    xml += "      </" + std::string(tag) + ">\n";
  }

  /// The end of the file: the appended blocks (raw bytes after '_'), then the closing tag.
  void finish(std::string& xml) const {
    if (encoding_ == VtkEncoding::zlib) {
      xml += "  <AppendedData encoding=\"raw\">\n   _";
      xml += appended_;
      xml += "\n  </AppendedData>\n";
    }
    xml += "</VTKFile>\n";
  }

 private:
  VtkEncoding encoding_;
  int level_;
  std::string appended_;
};

}  // namespace

void VtkArrays::scalars(std::string name, std::span<const double> values) {
  arrays_.push_back(make_array(std::move(name), VtkArray::Type::float64, 1, values));
}

void VtkArrays::vectors(std::string name, std::span<const Vec3> values) {
  arrays_.push_back(make_array(std::move(name), VtkArray::Type::float64, 3, flat(values)));
}

void VtkArrays::int32s(std::string name, std::span<const std::int32_t> values) {
  arrays_.push_back(make_array(std::move(name), VtkArray::Type::int32, 1, values));
}

void VtkArrays::int64s(std::string name, std::span<const std::int64_t> values) {
  arrays_.push_back(make_array(std::move(name), VtkArray::Type::int64, 1, values));
}

void VtkArrays::strings(std::string name, const std::vector<std::string>& values) {
  VtkArray a{std::move(name), VtkArray::Type::string, 1, values.size(), {}};
  for (const std::string& v : values) {
    if (v.find('\0') != std::string::npos)
      throw std::invalid_argument("VTK string with a NUL: " + a.name);
    a.bytes += v;
    a.bytes += '\0';
  }
  arrays_.push_back(std::move(a));
}

void VtkArrays::set_active(std::string scalars, std::string vectors) {
  scalars_ = std::move(scalars);
  vectors_ = std::move(vectors);
}

VtkPolyData::VtkPolyData(std::span<const Vec3> points)
    : points_(make_array("position", VtkArray::Type::float64, 3, flat(points))) {}

void VtkPolyData::lines(std::span<const std::int32_t> alpha, std::span<const std::int32_t> beta) {
  if (alpha.size() != beta.size())
    throw std::invalid_argument("VtkPolyData::lines: alpha and beta differ in length");
  line_connectivity_.reserve(line_connectivity_.size() + 2 * alpha.size());
  line_offsets_.reserve(line_offsets_.size() + alpha.size());
  for (std::size_t k = 0; k < alpha.size(); ++k) {
    line_connectivity_.push_back(alpha[k]);
    line_connectivity_.push_back(beta[k]);
    line_offsets_.push_back(static_cast<std::int64_t>(line_connectivity_.size()));
  }
}

void VtkPolyData::polygon(std::span<const std::int64_t> points) {
  poly_connectivity_.insert(poly_connectivity_.end(), points.begin(), points.end());
  poly_offsets_.push_back(static_cast<std::int64_t>(poly_connectivity_.size()));
}

std::string VtkPolyData::vtp(VtkEncoding encoding, int level) const {
  Writer w(encoding, level);
  // version 1.0: the first with header_type (VTK writes it so for UInt64 headers).
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\"";
  if (encoding == VtkEncoding::zlib) xml += " compressor=\"vtkZLibDataCompressor\"";
  xml += ">\n  <PolyData>\n";
  if (!field_data_.arrays().empty()) w.section(xml, "FieldData", field_data_, std::nullopt);
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(points()) +
         "\" NumberOfVerts=\"0\" NumberOfLines=\"" + std::to_string(line_count()) +
         "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(polygon_count()) + "\">\n";
  xml += "      <Points>\n";
  w.array(xml, points_, false);
  xml += "      </Points>\n";
  w.section(xml, "PointData", point_data_, points());
  w.cells(xml, "Lines", line_connectivity_, line_offsets_);
  w.cells(xml, "Polys", poly_connectivity_, poly_offsets_);
  w.section(xml, "CellData", cell_data_, line_count() + polygon_count());
  xml += "    </Piece>\n  </PolyData>\n";
  w.finish(xml);
  return xml;
}

}  // namespace bpm
