#include "apps/tfd/file_describers.h"

#include <algorithm>
#include <cctype>

namespace tfd::cli {

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}
}  // namespace

void FileDescribers::add(std::vector<std::string> suffixes, std::string what, Describer describer) {
  for (std::string& s : suffixes) s = lower(s);
  entries_.push_back({std::move(suffixes), std::move(what), std::move(describer)});
}

const Describer* FileDescribers::find(const std::filesystem::path& file) const {
  const std::string name = lower(file.filename().string());
  const Describer* best = nullptr;
  std::size_t bestLength = 0;
  for (const Entry& e : entries_)
    for (const std::string& s : e.suffixes)
      if (name.size() >= s.size() && name.ends_with(s) && s.size() > bestLength) {
        best = &e.describer;
        bestLength = s.size();
      }
  return best;
}

std::string FileDescribers::known() const {
  std::string out;
  for (const Entry& e : entries_) {
    std::string suffixes;
    for (const std::string& s : e.suffixes) suffixes += (suffixes.empty() ? "" : " ") + s;
    out += (out.empty() ? "" : ", ") + suffixes + " (" + e.what + ")";
  }
  return out;
}

}  // namespace tfd::cli
