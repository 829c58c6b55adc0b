// The error of every vectors / results file that cannot be read or is malformed: it names the
// file and the JSON pointer of the offending value, and makes `rotorcert vectors` exit with 2.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace rotorcert::vectors {

class VectorsError : public std::runtime_error {
 public:
  VectorsError(const std::filesystem::path& file, const std::string& json_path, const std::string& message)
      : std::runtime_error(file.string() + (json_path.empty() ? "" : " at " + json_path) + ": " + message),
        file_(file),
        json_path_(json_path) {}
  const std::filesystem::path& file() const { return file_; }
  /// JSON pointer of the offending value ("" for the whole file).
  const std::string& json_path() const { return json_path_; }

 private:
  std::filesystem::path file_;
  std::string json_path_;
};

}  // namespace rotorcert::vectors
