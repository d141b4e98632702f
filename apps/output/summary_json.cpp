#include "apps/output/summary_json.hpp"

#include <charconv>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

#include "apps/output/atomic_output.hpp"
#include "apps/output/finite_value.hpp"

namespace flexmoor::app {
namespace {

// A JSON string literal: quotes, backslashes and control characters escaped (RFC 8259, 7).
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

// The shortest decimal that reads back as the same double; always a valid JSON number.
std::string number(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

template <class Value>
void requireUniqueNames(const std::vector<std::pair<std::string, Value>>& entries,
                        const std::string& path, const char* member) {
  std::set<std::string> seen;
  for (const auto& [name, value] : entries)
    if (!seen.insert(name).second)
      throw std::runtime_error(path + ": \"" + name + "\" appears twice in " + member);
}

template <class Value, class Format>
void writeObject(std::ostream& os, const char* member,
                 const std::vector<std::pair<std::string, Value>>& entries, Format format) {
  os << "  " << quoted(member) << ": {";
  for (size_t i = 0; i < entries.size(); ++i)
    os << (i ? ",\n    " : "\n    ") << quoted(entries[i].first) << ": "
       << format(entries[i].second);
  os << (entries.empty() ? "}" : "\n  }");
}

}  // namespace

void writeSummaryJson(const std::string& path, const std::string& case_name,
                      const std::vector<std::pair<std::string, double>>& results,
                      const std::vector<std::pair<std::string, std::string>>& units) {
  for (const auto& [name, value] : results)
    requireFinite(value, path, [&name = name] { return "summary result \"" + name + "\""; });
  requireUniqueNames(results, path, "results");
  requireUniqueNames(units, path, "units");

  std::ostringstream text;
  text << "{\n  \"case\": " << quoted(case_name) << ",\n";
  writeObject(text, "results", results, number);
  text << ",\n";
  writeObject(text, "units", units, quoted);
  text << "\n}\n";

  writeFileAtomically(path, text.str());
}

}  // namespace flexmoor::app
