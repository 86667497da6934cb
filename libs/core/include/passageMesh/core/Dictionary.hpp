#pragma once
// A case dictionary: a small XML document whose root element holds one element per key
// (and, one level down, named sections), for example
//
//   <passageDict>
//     <pitch>0.85c</pitch>
//     <nO>30000</nO>
//   </passageDict>
//
// Reading checks every key against the list the caller allows, so a misspelt key is an
// error naming the key, the file and the line, never silently ignored. Lengths accept the
// suffix `c` (chords). File format: docs/case-format.md.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace passageMesh {

class Dictionary {
 public:
  explicit Dictionary(std::string rootName, std::string source = "");

  // Reads `file` and checks its root name and its keys: `allowedKeys` for plain entries
  // (empty: none allowed), `allowedSections` for nested sections (whose own keys are checked by the caller with
  // checkKeys). Throws InputError naming the file and line.
  static Dictionary read(const std::filesystem::path& file, const std::string& rootName,
                         const std::vector<std::string>& allowedKeys,
                         const std::vector<std::string>& allowedSections = {});

  const std::string& rootName() const { return rootName_; }
  const std::string& source() const { return source_; }

  bool has(const std::string& key) const;
  std::string text(const std::string& key) const;
  double scalar(const std::string& key) const;
  long integer(const std::string& key) const;
  // A length in metres; "0.5c" is 0.5 * chord.
  double length(const std::string& key, double chord) const;
  // The line of a key in its file (0 when not read from a file), for error messages.
  int line(const std::string& key) const;

  bool hasSection(const std::string& name) const;
  const Dictionary& section(const std::string& name) const;
  Dictionary& addSection(const std::string& name);

  // Throws InputError for a key outside `allowedKeys` (used for sections).
  void checkKeys(const std::vector<std::string>& allowedKeys) const;
  // Throws InputError for each key in `requiredKeys` that is missing.
  void require(const std::vector<std::string>& requiredKeys) const;

  void set(const std::string& key, const std::string& value);
  void set(const std::string& key, double value);  // written with 17 digits
  // A comment written just before the root's first entry, e.g. units.
  void setComment(std::string comment) { comment_ = std::move(comment); }

  std::string toXml() const;
  void write(const std::filesystem::path& file) const;  // atomic

 private:
  struct Entry {
    std::string key;
    std::string value;
    int line = 0;
  };
  const Entry& entry(const std::string& key) const;
  // Fills this dictionary from the children of an XML element (tinyxml2::XMLElement);
  // allowedKeys == nullptr accepts any plain key (a section's, checked later).
  void readChildren(const void* element, const std::vector<std::string>* allowedKeys,
                    const std::vector<std::string>& allowedSections);
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

  std::string rootName_;
  std::string source_;
  std::string comment_;
  int line_ = 0;
  std::vector<Entry> entries_;
  std::vector<std::pair<std::string, Dictionary>> sections_;
};

// Strict number parsing: the whole string must be one finite number.
bool parseFiniteDouble(const std::string& text, double& value);

}  // namespace passageMesh
