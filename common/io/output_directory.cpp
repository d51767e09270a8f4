#include "common/io/output_directory.hpp"

#include <fstream>
#include <system_error>

#include "common/core/error.hpp"

namespace mpfd::io {

void prepare_output_directory(const std::filesystem::path& dir, bool overwrite) {
  std::error_code ec;
  if (std::filesystem::exists(dir / "summary.json", ec) && !overwrite)
    throw Error("output folder " + dir.string() +
                " already holds a run (summary.json); choose another folder or pass --overwrite");
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("cannot create output folder " + dir.string() + ": " + ec.message());
  if (!std::filesystem::is_directory(dir))
    throw Error("output path " + dir.string() + " exists and is not a folder");
}

std::string path_in_run(const std::string& path, const std::filesystem::path& dir) {
  const std::filesystem::path relative =
      std::filesystem::absolute(path).lexically_normal().lexically_relative(
          std::filesystem::absolute(dir).lexically_normal());
  const bool inside = !relative.empty() && *relative.begin() != "..";
  return inside ? relative.string() : path;
}

void write_path_atomically(const std::filesystem::path& file,
                           const std::function<void(const std::filesystem::path&)>& write) {
  std::filesystem::path partial = file;
  partial += ".tmp";
  write(partial);
  std::error_code ec;
  std::filesystem::rename(partial, file, ec);
  if (ec)
    throw Error("cannot move " + partial.string() + " to " + file.string() + ": " + ec.message());
}

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write) {
  write_path_atomically(file, [&](const std::filesystem::path& partial) {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot open " + partial.string() + " for writing");
    write(out);
    out.flush();
    if (!out) throw Error("cannot write " + partial.string() + " (disk full?)");
  });
}

}  // namespace mpfd::io
