// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Output files are written to a temporary name and renamed into place, so that a failure
// never leaves a partial file behind.

#ifndef CGAL_CONFORMAL_REMESHING_TOOLS_ATOMIC_FILE_H
#define CGAL_CONFORMAL_REMESHING_TOOLS_ATOMIC_FILE_H

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>

namespace Conformal_remeshing_tools {

// Creates `directory` and its parents if they do not exist yet. Tools call it before their long
// work, so that an output directory they cannot use is reported at once, not after the run.
// Throws std::runtime_error naming the directory and the reason.
inline void prepare_output_directory(const std::string& directory)
{
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if(error)
    throw std::runtime_error("cannot create the directory '" + directory + "': " + error.message());
  if(!std::filesystem::is_directory(directory, error))
    throw std::runtime_error("'" + directory + "' is not a directory");
}

// Calls `write(temporary_path)`, which writes a whole file at that path (with the same
// extension as `path`, for writers that choose the format by extension), then renames it to
// `path`. Throws std::runtime_error naming the file on any failure.
inline void write_file_atomically_at(const std::string& path, const std::function<bool(const std::string&)>& write)
{
  const std::string::size_type dot = path.find_last_of('.');
  const std::string temporary = path + ".part" + (dot == std::string::npos ? std::string() : path.substr(dot));
  if(!write(temporary))
  {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + path + "'");
  }
  if(std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + reason);
  }
}

// Calls `write(stream)` on a temporary file beside `path`, then renames it to `path`.
// Throws std::runtime_error naming the file and the reason on any failure.
inline void write_file_atomically(const std::string& path, const std::function<bool(std::ostream&)>& write)
{
  write_file_atomically_at(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    return out && write(out) && out.flush();
  });
}

inline void write_file_atomically(const std::string& path, const std::string& content)
{
  write_file_atomically(path, [&](std::ostream& out) { out << content; return bool(out); });
}

} // namespace Conformal_remeshing_tools

#endif // CGAL_CONFORMAL_REMESHING_TOOLS_ATOMIC_FILE_H
