#pragma once
/// Checked access to a YAML document. A YamlField is a node plus where it came from (file, key path
/// such as `bond_materials.beam.poisson_ratio`, line), so every problem found while reading it
/// becomes an InputError that says where it is and how to fix it. Wrong types, unknown and
/// duplicate keys, and non-finite numbers are reported, never passed on.
///
/// yaml-cpp's non-const operator[] silently inserts missing keys; this wrapper never uses it and
/// instead looks keys up by iterating the map.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/vec3.hpp"

namespace bpm {

class YamlMap;

class YamlField {
 public:
  /// Parses a whole file; a missing file or a syntax error becomes an InputError with file and
  /// line, and so do a quoted value left open at the end of the file and a second YAML document.
  static YamlField load_file(const std::string& path);
  /// The same for YAML text that is not in a file; `name` stands for the file in messages.
  static YamlField load_text(const std::string& text, const std::string& name);

  YamlField(YAML::Node node, std::string key_path, std::shared_ptr<const std::string> file, int line);

  const std::string& key_path() const { return key_path_; }
  const std::string& file() const { return *file_; }
  int line() const { return line_; }  ///< 1-based
  /// "FILE:LINE: KEY.PATH", the prefix of every message about this field.
  std::string where() const;
  [[noreturn]] void fail(const std::string& what, const std::string& fix = "") const;

  bool is_null() const { return node_.IsNull(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_map() const { return node_.IsMap(); }

  double number() const;           ///< a finite number
  double positive() const;         ///< a finite number > 0
  double non_negative() const;     ///< a finite number >= 0
  std::int64_t integer() const;    ///< a decimal integer
  std::string text() const;        ///< a scalar as written
  bool boolean() const;            ///< true/false (also yes/no, on/off)
  Vec3 vec3() const;               ///< a list of exactly three numbers

  /// The items of a list.
  std::vector<YamlField> items() const;
  /// A map whose keys are user-chosen names (e.g. material names), in file order.
  std::vector<std::pair<std::string, YamlField>> entries() const;
  /// A map with a fixed set of keys; any other key is an error that lists the allowed ones.
  YamlMap map(std::initializer_list<std::string_view> allowed) const;

 private:
  std::string kind() const;  ///< "a list", "a map", ... for type errors
  std::string scalar_or_fail(std::string_view expected) const;

  YAML::Node node_;
  std::string key_path_;
  std::shared_ptr<const std::string> file_;
  int line_ = 0;
};

/// A checked map (see YamlField::map): keys are known to be allowed and unique.
class YamlMap {
 public:
  explicit YamlMap(YamlField self, std::vector<std::pair<std::string, YamlField>> entries)
      : self_(std::move(self)), entries_(std::move(entries)) {}

  const YamlField& self() const { return self_; }
  bool has(std::string_view key) const { return find(key).has_value(); }
  std::optional<YamlField> find(std::string_view key) const;
  /// The key's value; if missing, an error naming the key path with `fix` as the advice.
  YamlField require(std::string_view key, std::string_view fix) const;
  /// Exactly one of `keys` must be present: returns which one and its value.
  std::pair<std::string, YamlField> one_of(std::initializer_list<std::string_view> keys) const;

 private:
  YamlField self_;
  std::vector<std::pair<std::string, YamlField>> entries_;
};

}  // namespace bpm
