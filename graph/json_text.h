#pragma once
// JSON text helpers of the graph layer: strict parsing (duplicate keys are errors, syntax errors
// give line and column), the canonical pretty-printer used for saved graphs (deterministic, so
// save -> load -> save is byte-identical), compact one-line printing and short descriptions of
// values for "expected ..., found ..." messages.
#include <string>
#include <string_view>

#include "graph/json_fwd.h"

namespace tfd::graph {

/// Parses `text`. Throws LoadError(source, pointer, message) on a syntax error ("invalid JSON:
/// ... at line L, column C") or a duplicate object key (pointer to the key).
Json parseJsonText(std::string_view text, const std::string& source);

/// Canonical multi-line form: two-space indent; an array or object whose members are scalars
/// or arrays of scalars is written on one line when that line fits in 100 columns. Ends with a
/// newline.
std::string formatJson(const Json& json);

/// One line with ", " and ": " separators: `{"from": "a.b", "to": "c.d"}`, `[0.1, 0.0, 0.0]`.
std::string compactJson(const Json& json);

/// For error messages: the compact text, shortened to about 60 characters, or a description
/// such as "an object" / "an array of 5 elements" when long.
std::string describeJson(const Json& json);

/// `text` for a message: valid UTF-8 is kept, control characters and bytes that are not
/// UTF-8 become \xNN, so binary input is never echoed raw to a terminal.
std::string printableText(std::string_view text);

/// Appends one escaped token to a JSON pointer: pointerJoin("/nodes", "a/b") == "/nodes/a~1b".
std::string pointerJoin(std::string_view pointer, std::string_view token);
std::string pointerJoin(std::string_view pointer, std::size_t index);

}  // namespace tfd::graph
