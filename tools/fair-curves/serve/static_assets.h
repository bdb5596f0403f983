// Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
//
// fair-curves serve: the files of the editor page (tools/fair-curves/editor/), compiled into the
// program by CMake (serve/embed_assets.cmake writes editor_assets.cpp, regenerated when a file of
// the folder changes), or read from a folder given by --editor-dir (for page development). Only
// the files of that one folder are served: a name is letters, digits, '.', '_' and '-', not
// starting with '.', so that no request can name a directory, a parent (..) or a hidden file;
// a file of --editor-dir is opened without following a symbolic link.

#ifndef FAIR_CURVES_SERVE_STATIC_ASSETS_H
#define FAIR_CURVES_SERVE_STATIC_ASSETS_H

#include <cstddef>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fair_curves {
namespace serve {

/// One file of the page as compiled into the program.
struct Editor_asset {
  const char* name;
  const unsigned char* data;
  std::size_t size;
};

/// The table of the generated editor_assets.cpp (editor_asset_count entries).
extern const Editor_asset editor_assets[];
extern const std::size_t editor_asset_count;

/// Largest file served from --editor-dir.
constexpr std::size_t max_asset_size = std::size_t(16) << 20;

/// Whether `name` may name a file of the page (see the top of this file).
inline bool valid_asset_name(const std::string& name) {
  if (name.empty() || name.size() > 255 || name[0] == '.') return false;
  for (const char c : name)
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-'))
      return false;
  return true;
}

/// The Content-Type of a file of the page, by its extension.
inline std::string content_type(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  const std::string ext = dot == std::string::npos ? std::string() : name.substr(dot + 1);
  if (ext == "html" || ext == "htm") return "text/html; charset=utf-8";
  if (ext == "css") return "text/css; charset=utf-8";
  if (ext == "js" || ext == "mjs") return "text/javascript; charset=utf-8";
  if (ext == "json") return "application/json";
  if (ext == "svg") return "image/svg+xml";
  if (ext == "png") return "image/png";
  if (ext == "ico") return "image/x-icon";
  if (ext == "txt" || ext == "md") return "text/plain; charset=utf-8";
  if (ext == "csv") return "text/csv; charset=utf-8";
  if (ext == "woff2") return "font/woff2";
  return "application/octet-stream";
}

/// The contents of the page's file `name` (compiled in, or from `editor_dir` when not empty);
/// false when there is no such file.
inline bool find_asset(const std::string& editor_dir, const std::string& name, std::string& contents) {
  if (!valid_asset_name(name)) return false;
  if (editor_dir.empty()) {
    for (std::size_t i = 0; i < editor_asset_count; ++i)
      if (name == editor_assets[i].name) {
        contents.assign(reinterpret_cast<const char*>(editor_assets[i].data), editor_assets[i].size);
        return true;
      }
    return false;
  }
  const std::string path = editor_dir + "/" + name;
  // O_NONBLOCK: opening a FIFO (or a device) named like a page file must not block the thread
  // (review finding 11); only a regular file is then served, and a regular file ignores the flag.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return false;
  struct stat st;
  bool ok = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) <= max_asset_size;
  if (ok) {
    contents.resize(static_cast<std::size_t>(st.st_size));
    std::size_t done = 0;
    while (ok && done < contents.size()) {
      const ssize_t got = ::read(fd, &contents[done], contents.size() - done);
      if (got <= 0) ok = false;
      else done += static_cast<std::size_t>(got);
    }
  }
  ::close(fd);
  return ok;
}

} // namespace serve
} // namespace fair_curves

#endif // FAIR_CURVES_SERVE_STATIC_ASSETS_H
