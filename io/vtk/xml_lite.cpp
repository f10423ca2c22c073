#include "io/vtk/xml_lite.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "io/text_scanner.h"

namespace tfd::io {

const std::string* XmlElement::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes) {
    if (k == key) return &v;
  }
  return nullptr;
}

const XmlElement* XmlElement::child(std::string_view childName) const {
  for (const auto& c : children) {
    if (c.name == childName) return &c;
  }
  return nullptr;
}

std::vector<const XmlElement*> XmlElement::childrenNamed(std::string_view childName) const {
  std::vector<const XmlElement*> out;
  for (const auto& c : children) {
    if (c.name == childName) out.push_back(&c);
  }
  return out;
}

namespace {

class Parser {
 public:
  Parser(std::string_view data, const std::string& file) : d_(data), file_(file) {}

  XmlDocument parse() {
    XmlDocument doc;
    std::vector<XmlElement*> stack;
    bool haveRoot = false;
    while (pos_ < d_.size()) {
      if (d_[pos_] != '<') {
        const std::size_t end = std::min(d_.find('<', pos_), d_.size());
        const std::string_view text = d_.substr(pos_, end - pos_);
        if (!stack.empty()) {
          stack.back()->text += decode(text);
        } else if (!std::all_of(text.begin(), text.end(),
                                [](char c) { return std::isspace((unsigned char)c); })) {
          fail("text outside the root element");
        }
        advance(end);
        continue;
      }
      if (starts("<?")) {
        skipPast("?>");
      } else if (starts("<!--")) {
        skipPast("-->");
      } else if (starts("<![CDATA[")) {
        const std::size_t end = d_.find("]]>", pos_);
        if (end == std::string_view::npos) fail("unterminated CDATA section");
        if (!stack.empty()) stack.back()->text += std::string(d_.substr(pos_ + 9, end - pos_ - 9));
        advance(end + 3);
      } else if (starts("<!")) {
        skipPast(">");
      } else if (starts("</")) {
        advance(pos_ + 2);
        const std::string name = readName();
        skipSpace();
        expect('>');
        if (stack.empty() || stack.back()->name != name) {
          fail("closing tag </" + name + "> does not match " +
               (stack.empty() ? std::string("any open element")
                              : "<" + stack.back()->name + "> opened at line " +
                                    std::to_string(stack.back()->line)));
        }
        stack.pop_back();
      } else {
        const int line = line_;
        advance(pos_ + 1);
        XmlElement e;
        e.name = readName();
        e.line = line;
        bool selfClosing = false;
        for (;;) {
          skipSpace();
          if (pos_ >= d_.size()) fail("unterminated tag <" + e.name + ">");
          if (d_[pos_] == '/') {
            advance(pos_ + 1);
            expect('>');
            selfClosing = true;
            break;
          }
          if (d_[pos_] == '>') {
            advance(pos_ + 1);
            break;
          }
          std::string key = readName();
          skipSpace();
          expect('=');
          skipSpace();
          if (pos_ >= d_.size() || (d_[pos_] != '"' && d_[pos_] != '\'')) {
            fail("expected a quoted value for attribute '" + key + "'");
          }
          const char quote = d_[pos_];
          const std::size_t end = d_.find(quote, pos_ + 1);
          if (end == std::string_view::npos) fail("unterminated value of attribute '" + key + "'");
          std::string value = decode(d_.substr(pos_ + 1, end - pos_ - 1));
          advance(end + 1);
          e.attributes.emplace_back(std::move(key), std::move(value));
        }
        if (e.name == "AppendedData" && !selfClosing) {
          // Raw bytes follow the '_' marker: stop parsing here.
          const std::size_t mark = d_.find('_', pos_);
          if (mark == std::string_view::npos) fail("<AppendedData> without the '_' marker");
          doc.appendedStart = mark + 1;
          doc.appended = std::move(e);
          finish(haveRoot);
          return doc;
        }
        XmlElement* added;
        if (stack.empty()) {
          if (haveRoot) fail("a second root element <" + e.name + ">");
          doc.root = std::move(e);
          haveRoot = true;
          added = &doc.root;
        } else {
          stack.back()->children.push_back(std::move(e));
          added = &stack.back()->children.back();
        }
        if (!selfClosing) stack.push_back(added);
      }
    }
    if (!stack.empty()) {
      fail("the file ended inside <" + stack.back()->name + "> opened at line " +
           std::to_string(stack.back()->line));
    }
    finish(haveRoot);
    return doc;
  }

 private:
  void finish(bool haveRoot) const {
    if (!haveRoot) fail("no XML element found");
  }
  bool starts(std::string_view s) const { return d_.substr(pos_, s.size()) == s; }
  void advance(std::size_t to) {
    line_ += int(std::count(d_.begin() + pos_, d_.begin() + to, '\n'));
    pos_ = to;
  }
  void skipPast(std::string_view s) {
    const std::size_t end = d_.find(s, pos_);
    if (end == std::string_view::npos)
      fail("unterminated '" + std::string(d_.substr(pos_, 4)) + "'");
    advance(end + s.size());
  }
  void skipSpace() {
    std::size_t p = pos_;
    while (p < d_.size() && std::isspace((unsigned char)d_[p])) ++p;
    advance(p);
  }
  void expect(char c) {
    if (pos_ >= d_.size() || d_[pos_] != c) fail(std::string("expected '") + c + "'");
    advance(pos_ + 1);
  }
  std::string readName() {
    const std::size_t start = pos_;
    while (pos_ < d_.size() && (std::isalnum((unsigned char)d_[pos_]) || d_[pos_] == '_' ||
                                d_[pos_] == ':' || d_[pos_] == '-' || d_[pos_] == '.')) {
      ++pos_;
    }
    if (pos_ == start) fail("expected a name");
    return std::string(d_.substr(start, pos_ - start));
  }
  std::string decode(std::string_view s) const {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i] != '&') {
        out += s[i];
        continue;
      }
      const std::size_t semi = s.find(';', i);
      const std::string_view entity = s.substr(i + 1, semi - i - 1);
      if (semi == std::string_view::npos) fail("unterminated entity");
      if (entity == "lt")
        out += '<';
      else if (entity == "gt")
        out += '>';
      else if (entity == "amp")
        out += '&';
      else if (entity == "quot")
        out += '"';
      else if (entity == "apos")
        out += '\'';
      else if (!entity.empty() && entity[0] == '#') {
        const bool hex = entity.size() > 1 && (entity[1] == 'x' || entity[1] == 'X');
        const long code =
            std::strtol(std::string(entity.substr(hex ? 2 : 1)).c_str(), nullptr, hex ? 16 : 10);
        if (code > 0 && code < 128) {
          out += char(code);
        } else {
          out += '?';
        }
      } else {
        fail("unknown entity '&" + std::string(entity) + ";'");
      }
      i = semi;
    }
    return out;
  }
  /// Messages quote names and text from the file: made printable (no raw bytes reach a terminal).
  [[noreturn]] void fail(const std::string& message) const {
    throw core::Error("file '" + file_ + "', line " + std::to_string(line_) + ": " +
                      printableText(message));
  }

  std::string_view d_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

XmlDocument parseXml(std::string_view data, const std::string& fileName) {
  return Parser(data, fileName).parse();
}

}  // namespace tfd::io
