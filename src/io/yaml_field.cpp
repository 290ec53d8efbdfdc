#include "io/yaml_field.hpp"

#include <fmt/core.h>
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "io/parse_number.hpp"

namespace bpm {
namespace {

std::string join(std::initializer_list<std::string_view> words) {
  std::string s;
  for (const auto w : words) s += (s.empty() ? "" : ", ") + std::string(w);
  return s;
}

std::string child_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

/// yaml-cpp marks are 0-based and -1 for nodes without a source position.
int line_of(const YAML::Mark& mark, int fallback) { return mark.line >= 0 ? mark.line + 1 : fallback; }

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot read the file", "check that it is readable");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string_view without_trailing_space(std::string_view text) {
  const auto last = text.find_last_not_of(" \t\r\n");
  return last == std::string_view::npos ? std::string_view{} : text.substr(0, last + 1);
}

/// Records where each document starts and whether it is a lone null, for refuse_stuck_parser.
class DocumentMarks : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override {
    start = mark;
    events = 0;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { event(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { event(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override { event(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    event(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    event(mark);
  }
  void OnMapEnd() override {}

  YAML::Mark start = YAML::Mark::null_mark();
  YAML::Mark first_node = YAML::Mark::null_mark();  ///< of the last document
  int events = 0;

 private:
  void event(const YAML::Mark& mark) {
    if (events++ == 0) first_node = mark;
  }
};

/// yaml-cpp 0.7's LoadAll loops for ever, allocating, on a flow indicator outside brackets (a
/// line starting with ','; jbeder/yaml-cpp#1040, fixed upstream after 0.8): the parser hands out
/// the same empty document again and again without moving on. This walks the documents with
/// yaml-cpp's event parser first and refuses a document that starts where the last one did.
void refuse_stuck_parser(const std::string& path, const std::string& text) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentMarks marks;
  YAML::Mark previous = YAML::Mark::null_mark();
  for (int documents = 0; parser.HandleNextDocument(marks); ++documents) {
    const YAML::Mark at = marks.events > 0 ? marks.first_node : marks.start;
    if (documents > 0 && at.pos == previous.pos) {
      throw InputError(fmt::format("{}:{}", path, line_of(at, 1)),
                       "YAML syntax error: the parser cannot get past this point (a ',', '[', ']', '{' or '}' "
                       "outside a bracketed list or map?)",
                       "put the list in brackets, [a, b], or remove the stray character");
    }
    previous = at;
  }
}

struct LastScalar {
  YAML::Mark mark = YAML::Mark::null_mark();
  bool plain = true;
};

/// The scalar that comes last in the document (largest position).
void find_last_scalar(const YAML::Node& node, LastScalar& last) {
  if (node.IsScalar() && node.Mark().pos > last.mark.pos) last = {node.Mark(), node.Tag() == "?"};
  if (node.IsSequence()) {
    for (const auto& item : node) find_last_scalar(item, last);
  }
  if (node.IsMap()) {
    for (const auto& entry : node) {
      find_last_scalar(entry.first, last);
      find_last_scalar(entry.second, last);
    }
  }
}

/// yaml-cpp 0.7 accepts a quoted value that is still open at the end of the input when the input
/// ends with a line break: `description: "abc` followed by more lines makes them all the
/// description. Such a value swallows everything, so it is the document's last scalar. If that
/// scalar is not plain, the text is parsed once more without its trailing whitespace, where
/// yaml-cpp does raise "illegal EOF in scalar" for an open quote.
void refuse_unclosed_quote(const std::string& path, const std::string& text,
                           const YAML::Node& last_document) {
  LastScalar last;
  find_last_scalar(last_document, last);
  if (last.plain) return;
  try {
    const std::string trimmed(without_trailing_space(text));
    refuse_stuck_parser(path, trimmed);
    YAML::LoadAll(trimmed);
  } catch (const YAML::ParserException& e) {
    if (e.msg != YAML::ErrorMsg::EOF_IN_SCALAR) return;
    throw InputError(fmt::format("{}:{}", path, line_of(last.mark, e.mark.line + 1)),
                     "a quoted value that starts on this line is never closed, so the rest of the "
                     "file would be read as part of it",
                     "add the closing quote (\" or ') at the end of the value");
  }
}

/// yaml-cpp's LoadFile keeps the first document and silently drops the others. An empty one (a
/// stray '---' or '...' at the end) loses nothing; one with content is refused.
void refuse_extra_documents(const std::string& path, const std::vector<YAML::Node>& documents) {
  for (std::size_t i = 1; i < documents.size(); ++i) {
    if (documents[i].IsNull()) continue;
    throw InputError(
        fmt::format("{}:{}", path, line_of(documents[i].Mark(), 1)),
        "a second YAML document starts here (after a '---' line); a file holds one document",
        "remove the '---' line to make it part of the first, or move it to a file of its own");
  }
}

}  // namespace

YamlField YamlField::load_file(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) {
    throw InputError(path, "scenario file not found", "check the path; a relative path starts at the current directory");
  }
  return load_text(file_text(path), path);
}

YamlField YamlField::load_text(const std::string& text, const std::string& path) {
  auto file = std::make_shared<const std::string>(path);
  std::vector<YAML::Node> documents;
  try {
    refuse_stuck_parser(path, text);
    documents = YAML::LoadAll(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(fmt::format("{}:{}", path, e.mark.line + 1), "YAML syntax error: " + e.msg,
                     "fix the indentation, brackets or quotes near this line");
  } catch (const YAML::Exception& e) {
    throw InputError(path, std::string("cannot read the file: ") + e.what(), "check that it is readable YAML");
  }
  if (!documents.empty()) refuse_unclosed_quote(path, text, documents.back());
  refuse_extra_documents(path, documents);
  return YamlField(documents.empty() ? YAML::Node() : documents.front(), "", file, 1);
}

YamlField::YamlField(YAML::Node node, std::string key_path, std::shared_ptr<const std::string> file, int line)
    : node_(std::move(node)), key_path_(std::move(key_path)), file_(std::move(file)), line_(line) {}

std::string YamlField::where() const {
  return key_path_.empty() ? fmt::format("{}:{}", *file_, line_) : fmt::format("{}:{}: {}", *file_, line_, key_path_);
}

void YamlField::fail(const std::string& what, const std::string& fix) const { throw InputError(where(), what, fix); }

std::string YamlField::kind() const {
  if (node_.IsNull()) return "nothing";
  if (node_.IsSequence()) return "a list";
  if (node_.IsMap()) return "a map";
  return "'" + node_.Scalar() + "'";
}

std::string YamlField::scalar_or_fail(std::string_view expected) const {
  if (!node_.IsScalar()) fail(fmt::format("expected {}, got {}", expected, kind()), fmt::format("write {} here", expected));
  return node_.Scalar();
}

double YamlField::number() const {
  const auto v = parse_double(scalar_or_fail("a number"));
  if (!v) fail("expected a finite number, got " + kind(), "write a number such as 0.4 or 2e11");
  return *v;
}

double YamlField::positive() const {
  const double v = number();
  if (!(v > 0.0)) fail(fmt::format("must be greater than 0, got {}", v), "use a positive value");
  return v;
}

double YamlField::non_negative() const {
  const double v = number();
  if (v < 0.0) fail(fmt::format("must not be negative, got {}", v), "use 0 or a positive value");
  return v;
}

std::int64_t YamlField::integer() const {
  const auto v = parse_int64(scalar_or_fail("an integer"));
  if (!v) fail("expected an integer, got " + kind(), "write a whole number such as 10");
  return *v;
}

std::string YamlField::text() const { return scalar_or_fail("a text value"); }

bool YamlField::boolean() const {
  scalar_or_fail("true or false");
  bool value = false;
  if (!YAML::convert<bool>::decode(node_, value)) fail("expected true or false, got " + kind(), "write true or false");
  return value;
}

Vec3 YamlField::vec3() const {
  const auto xs = items();
  if (xs.size() != 3) fail(fmt::format("expected a list of 3 numbers, got {} items", xs.size()), "write [x, y, z]");
  return {xs[0].number(), xs[1].number(), xs[2].number()};
}

std::vector<YamlField> YamlField::items() const {
  if (!node_.IsSequence()) fail("expected a list, got " + kind(), "write a YAML list such as [a, b] or '- a' lines");
  std::vector<YamlField> out;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    const YAML::Node item = node_[i];
    // A null item (`- `) has no useful mark of its own; the list's line is the best we have.
    const int line = item.IsNull() ? line_ : line_of(item.Mark(), line_);
    out.emplace_back(item, fmt::format("{}[{}]", key_path_, i), file_, line);
  }
  return out;
}

std::vector<std::pair<std::string, YamlField>> YamlField::entries() const {
  if (!node_.IsMap()) fail("expected a map of 'key: value' lines, got " + kind(), "write 'key: value' entries");
  std::vector<std::pair<std::string, YamlField>> out;
  std::set<std::string> seen;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    // The key's line, not the value's: for an empty value yaml-cpp points at the next line.
    const int line = line_of(it->first.Mark(), line_);
    if (!it->first.IsScalar()) {
      throw InputError(fmt::format("{}:{}: {}", *file_, line, key_path_), "a key must be a plain name",
                       "write 'name: value'");
    }
    const std::string key = it->first.Scalar();
    YamlField value(it->second, child_path(key_path_, key), file_, line);
    if (!seen.insert(key).second) value.fail("duplicate key", "give each key once");
    out.emplace_back(key, std::move(value));
  }
  return out;
}

YamlMap YamlField::map(std::initializer_list<std::string_view> allowed) const {
  auto fields = entries();
  for (const auto& [key, value] : fields) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      value.fail("unknown key '" + key + "'", "allowed keys here: " + join(allowed));
    }
  }
  return YamlMap(*this, std::move(fields));
}

std::optional<YamlField> YamlMap::find(std::string_view key) const {
  for (const auto& [k, v] : entries_) {
    if (k == key) return v;
  }
  return std::nullopt;
}

YamlField YamlMap::require(std::string_view key, std::string_view fix) const {
  if (auto v = find(key)) return *v;
  throw InputError(fmt::format("{}:{}: {}", self_.file(), self_.line(), child_path(self_.key_path(), key)),
                   "missing required key '" + std::string(key) + "'", std::string(fix));
}

std::pair<std::string, YamlField> YamlMap::one_of(std::initializer_list<std::string_view> keys) const {
  std::optional<std::pair<std::string, YamlField>> found;
  for (const auto key : keys) {
    if (auto v = find(key)) {
      if (found) v->fail(fmt::format("give only one of {}; '{}' is already given", join(keys), found->first));
      found.emplace(std::string(key), *v);
    }
  }
  if (!found) self_.fail("needs one of: " + join(keys), "add exactly one of these keys");
  return *found;
}

}  // namespace bpm
