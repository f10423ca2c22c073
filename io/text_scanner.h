#pragma once
// Line-oriented scanning of text mesh files with precise error messages (file, line, what was
// expected, what was found). Internal helper of the io readers.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "io/file_bytes.h"

namespace tfd::io {

class TextScanner {
 public:
  /// Scans `text` (the contents of `fileName`, for messages) starting at byte `offset`, whose
  /// line number is `firstLine`. Text after `comment` on a line is ignored (0: no comments).
  TextScanner(std::string_view text, std::string fileName, char comment = '#',
              std::size_t offset = 0, int firstLine = 1);

  /// Moves to the next line that has a token; false at the end of the text.
  bool nextLine();
  /// The current line without its comment and line ending.
  std::string_view line() const { return line_; }
  int lineNumber() const { return lineNumber_; }
  /// The next whitespace-separated token of the current line; empty at its end.
  std::string_view token();
  bool atLineEnd();
  /// The next token as a finite number / an integer; otherwise fails naming `what`.
  double number(std::string_view what);
  long long integer(std::string_view what);
  /// Fails if the current line has more tokens.
  void expectLineEnd(std::string_view what);
  /// Byte offset just after the current line (its line ending included).
  std::size_t nextOffset() const { return next_; }

  /// "file 'x', line N: message".
  [[noreturn]] void fail(const std::string& message) const;
  /// "file 'x': message (file ended at line N)".
  [[noreturn]] void failAtEnd(const std::string& message) const;
  const std::string& fileName() const { return fileName_; }

 private:
  std::string_view text_;
  std::string fileName_;
  char comment_;
  std::size_t next_;
  std::string_view line_;
  std::size_t pos_ = 0;  // inside line_
  int lineNumber_;
  int lastLine_;  // number of the last line read, for messages at the end
};

/// Parses a whole token as a finite double (a leading '+' is allowed); false otherwise.
bool parseNumber(std::string_view token, double& value);
/// Parses a whole token as a decimal integer (a leading '+' is allowed); false otherwise.
bool parseInteger(std::string_view token, long long& value);

/// `text` for a message: valid UTF-8 is kept, control characters and bytes that are not
/// UTF-8 become \xNN, so binary input is never echoed raw to a terminal.
std::string printableText(std::string_view text);

/// "'abc'" for a token, "the end of the line" for an empty one: for "found ..." messages
/// (printableText).
std::string describeToken(std::string_view token);

}  // namespace tfd::io
