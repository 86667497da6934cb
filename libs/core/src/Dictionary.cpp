#include "passageMesh/core/Dictionary.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "passageMesh/core/AtomicFile.hpp"
#include "passageMesh/core/InputError.hpp"
#include "passageMesh/core/JoinedWords.hpp"
#include "passageMesh/core/NumberFormat.hpp"

namespace passageMesh {

namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

}  // namespace

bool parseFiniteDouble(const std::string& text, double& value) {
  const std::string t = trim(text);
  if (t.empty()) return false;
  const char* begin = t.data();
  if (*begin == '+') ++begin;  // from_chars refuses a leading '+'
  const char* end = t.data() + t.size();
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

Dictionary::Dictionary(std::string rootName, std::string source)
    : rootName_(std::move(rootName)), source_(std::move(source)) {}

Dictionary Dictionary::read(const std::filesystem::path& file, const std::string& rootName,
                            const std::vector<std::string>& allowedKeys,
                            const std::vector<std::string>& allowedSections) {
  const std::string name = file.string();
  if (!std::filesystem::is_regular_file(file))
    throw InputError(name, 0, "file not found (expected an XML dictionary <" + rootName + ">)");
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(name.c_str()) != tinyxml2::XML_SUCCESS) {
    const std::string why = doc.ErrorStr() ? doc.ErrorStr() : "unknown error";
    throw InputError(name, doc.ErrorLineNum(), "malformed XML: " + why);
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root) throw InputError(name, 0, "empty XML document, expected <" + rootName + ">");
  if (rootName != root->Name())
    throw InputError(name, root->GetLineNum(),
                     "root element is <" + std::string(root->Name()) + ">, expected <" +
                         rootName + ">");
  Dictionary dict(rootName, name);
  dict.line_ = root->GetLineNum();
  dict.readChildren(root, &allowedKeys, allowedSections);
  return dict;
}

void Dictionary::readChildren(const void* xmlElement,
                              const std::vector<std::string>* allowedKeys,
                              const std::vector<std::string>& allowedSections) {
  const auto& element = *static_cast<const tinyxml2::XMLElement*>(xmlElement);
  for (const auto* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    const std::string key = child->Name();
    const int line = child->GetLineNum();
    if (child->FirstChildElement()) {
      if (!contains(allowedSections, key))
        throw InputError(source_, line,
                         "unknown section <" + key + "> in <" + rootName_ + ">" +
                             (allowedSections.empty()
                                  ? ""
                                  : " (allowed: " + joinedWords(allowedSections, ", ") + ")"));
      if (hasSection(key)) throw InputError(source_, line, "section <" + key + "> given twice");
      Dictionary& sub = addSection(key);
      sub.line_ = line;
      // A section's keys are checked by the caller (checkKeys), which knows what it holds.
      sub.readChildren(child, nullptr, {});
      continue;
    }
    if (allowedKeys && !contains(*allowedKeys, key))
      throw InputError(source_, line,
                       "unknown key <" + key + "> in <" + rootName_ + ">" +
                           (allowedKeys->empty() ? "" : " (allowed: " + joinedWords(*allowedKeys, ", ") + ")"));
    if (has(key)) throw InputError(source_, line, "key <" + key + "> given twice");
    entries_.push_back({key, trim(child->GetText() ? child->GetText() : ""), line});
  }
}

bool Dictionary::has(const std::string& key) const {
  return std::any_of(entries_.begin(), entries_.end(),
                     [&](const Entry& e) { return e.key == key; });
}

const Dictionary::Entry& Dictionary::entry(const std::string& key) const {
  for (const auto& e : entries_)
    if (e.key == key) return e;
  throw InputError(source_.empty() ? rootName_ : source_, line_,
                   "missing key <" + key + "> in <" + rootName_ + ">");
}

void Dictionary::fail(const std::string& key, const std::string& what) const {
  const Entry& e = entry(key);
  throw InputError(source_.empty() ? rootName_ : source_, e.line,
                   "<" + key + ">: " + what + ", got '" + e.value + "'");
}

std::string Dictionary::text(const std::string& key) const { return entry(key).value; }

int Dictionary::line(const std::string& key) const { return entry(key).line; }

double Dictionary::scalar(const std::string& key) const {
  double value = 0;
  if (!parseFiniteDouble(entry(key).value, value)) fail(key, "expected a finite number");
  return value;
}

long Dictionary::integer(const std::string& key) const {
  const std::string& t = entry(key).value;
  long value = 0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || ptr != t.data() + t.size()) fail(key, "expected an integer");
  return value;
}

double Dictionary::length(const std::string& key, double chord) const {
  std::string t = entry(key).value;
  const bool inChords = !t.empty() && t.back() == 'c';
  if (inChords) t.pop_back();
  double value = 0;
  if (!parseFiniteDouble(t, value))
    fail(key, "expected a length in metres or in chords with the suffix c (e.g. 0.5c)");
  return inChords ? value * chord : value;
}

bool Dictionary::hasSection(const std::string& name) const {
  return std::any_of(sections_.begin(), sections_.end(),
                     [&](const auto& s) { return s.first == name; });
}

const Dictionary& Dictionary::section(const std::string& name) const {
  for (const auto& s : sections_)
    if (s.first == name) return s.second;
  throw InputError(source_.empty() ? rootName_ : source_, line_,
                   "missing section <" + name + "> in <" + rootName_ + ">");
}

Dictionary& Dictionary::addSection(const std::string& name) {
  sections_.emplace_back(name, Dictionary(name, source_));
  return sections_.back().second;
}

void Dictionary::checkKeys(const std::vector<std::string>& allowedKeys) const {
  for (const auto& e : entries_)
    if (!contains(allowedKeys, e.key))
      throw InputError(source_, e.line,
                       "unknown key <" + e.key + "> in <" + rootName_ +
                           "> (allowed: " + joinedWords(allowedKeys, ", ") + ")");
}

void Dictionary::require(const std::vector<std::string>& requiredKeys) const {
  for (const auto& key : requiredKeys) (void)entry(key);
}

void Dictionary::set(const std::string& key, const std::string& value) {
  for (auto& e : entries_)
    if (e.key == key) {
      e.value = value;
      return;
    }
  entries_.push_back({key, value, 0});
}

void Dictionary::set(const std::string& key, double value) { set(key, formatExact(value)); }

namespace {

void writeChildren(tinyxml2::XMLDocument& doc, tinyxml2::XMLNode& parent,
                   const std::vector<std::pair<std::string, std::string>>& entries) {
  for (const auto& [key, value] : entries) {
    auto* element = doc.NewElement(key.c_str());
    element->SetText(value.c_str());
    parent.InsertEndChild(element);
  }
}

}  // namespace

std::string Dictionary::toXml() const {
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  auto* root = doc.NewElement(rootName_.c_str());
  doc.InsertEndChild(root);
  if (!comment_.empty()) root->InsertEndChild(doc.NewComment((" " + comment_ + " ").c_str()));
  std::vector<std::pair<std::string, std::string>> plain;
  for (const auto& e : entries_) plain.emplace_back(e.key, e.value);
  writeChildren(doc, *root, plain);
  for (const auto& [name, sub] : sections_) {
    auto* element = doc.NewElement(name.c_str());
    if (!sub.comment_.empty())
      element->InsertEndChild(doc.NewComment((" " + sub.comment_ + " ").c_str()));
    std::vector<std::pair<std::string, std::string>> subEntries;
    for (const auto& e : sub.entries_) subEntries.emplace_back(e.key, e.value);
    writeChildren(doc, *element, subEntries);
    root->InsertEndChild(element);
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

void Dictionary::write(const std::filesystem::path& file) const {
  writeFileAtomically(file, toXml());
}

}  // namespace passageMesh
