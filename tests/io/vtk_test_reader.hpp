#pragma once
// A small reader of the .vtp files bpmkit writes (io/vtk_polydata.hpp), ASCII or appended zlib,
// for the tests: the XML part and the values of a named array. Independent of the writer except
// for vtk_zlib_unblock (itself tested against zlib in vtk_polydata_test.cpp).
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/vtk_zlib.hpp"

namespace bpm::test {

inline constexpr const char* kAppendedTag = "<AppendedData encoding=\"raw\">";

/// The file with its appended bytes cut out: XML only (what a well-formedness check can read).
inline std::string vtk_xml(const std::string& file) {
  const auto at = file.find(kAppendedTag);
  if (at == std::string::npos) return file;
  return file.substr(0, at) + kAppendedTag + "</AppendedData>\n</VTKFile>\n";
}

/// The appended bytes (after the '_'); empty for an ASCII file.
inline std::string_view vtk_appended(const std::string& file) {
  const auto at = file.find(kAppendedTag);
  if (at == std::string::npos) return {};
  const auto underscore = file.find('_', at);
  return std::string_view(file).substr(underscore + 1);
}

/// The opening tag of the first array called `name` (in `section`, e.g. "CellData", if given)
/// and the text after it; throws when there is none.
inline std::pair<std::string, std::string> vtk_array_element(const std::string& file,
                                                             const std::string& name,
                                                             const std::string& section = "") {
  const std::string xml = vtk_xml(file);
  std::size_t begin = 0, end = xml.size();
  if (!section.empty()) {
    begin = xml.find("<" + section);
    end = xml.find("</" + section + ">", begin);
    if (begin == std::string::npos || end == std::string::npos)
      throw std::runtime_error("no section " + section);
  }
  const auto at = xml.find("Name=\"" + name + "\"", begin);
  if (at == std::string::npos || at > end)
    throw std::runtime_error("no array " + name + " in " + section);
  const auto open = xml.rfind('<', at), close = xml.find('>', at);
  return {xml.substr(open, close + 1 - open),
          xml.substr(close + 1, xml.find('<', close) - close - 1)};
}

inline std::string vtk_attribute(const std::string& tag, const std::string& key) {
  const auto at = tag.find(" " + key + "=\"");
  if (at == std::string::npos) return {};
  const auto start = at + key.size() + 3;
  return tag.substr(start, tag.find('"', start) - start);
}

/// The values of array `name` as T (the type the file says it has: the caller knows it).
template <class T>
std::vector<T> vtk_values(const std::string& file, const std::string& name,
                          const std::string& section = "") {
  const auto [tag, text] = vtk_array_element(file, name, section);
  std::vector<T> values;
  if (vtk_attribute(tag, "format") == "appended") {
    const std::size_t offset = std::stoull(vtk_attribute(tag, "offset"));
    const std::string raw = vtk_zlib_unblock(vtk_appended(file).substr(offset));
    if (raw.size() % sizeof(T) != 0)
      throw std::runtime_error(name + ": size is not a multiple of the type");
    values.resize(raw.size() / sizeof(T));
    if (!raw.empty()) std::memcpy(values.data(), raw.data(), raw.size());
    return values;
  }
  std::istringstream in(text);
  for (T v; in >> v;) values.push_back(v);
  return values;
}

/// The values of a numeric array of any type, as doubles.
inline std::vector<double> vtk_numbers(const std::string& file, const std::string& name,
                                       const std::string& section = "") {
  const std::string type = vtk_attribute(vtk_array_element(file, name, section).first, "type");
  auto as_doubles = [](const auto& v) { return std::vector<double>(v.begin(), v.end()); };
  if (type == "Int32") return as_doubles(vtk_values<std::int32_t>(file, name, section));
  if (type == "Int64") return as_doubles(vtk_values<std::int64_t>(file, name, section));
  if (type == "Float64") return vtk_values<double>(file, name, section);
  throw std::runtime_error(name + ": unexpected type " + type);
}

/// A string array (type "String"): its strings.
inline std::vector<std::string> vtk_strings(const std::string& file, const std::string& name) {
  const auto [tag, text] = vtk_array_element(file, name);
  std::string raw;
  if (vtk_attribute(tag, "format") == "appended") {
    raw = vtk_zlib_unblock(vtk_appended(file).substr(std::stoull(vtk_attribute(tag, "offset"))));
  } else {
    std::istringstream in(text);
    for (int c; in >> c;) raw.push_back(static_cast<char>(c));
  }
  std::vector<std::string> out;
  for (std::size_t start = 0; start < raw.size();) {
    const auto nul = raw.find('\0', start);
    out.push_back(raw.substr(start, nul - start));
    start = nul == std::string::npos ? raw.size() : nul + 1;
  }
  return out;
}

}  // namespace bpm::test
