// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A minimal streaming JSON writer for the tools' reports (the library itself writes no files).

#ifndef CGAL_CONFORMAL_REMESHING_TOOLS_JSON_WRITER_H
#define CGAL_CONFORMAL_REMESHING_TOOLS_JSON_WRITER_H

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace Conformal_remeshing_tools {

class Json_writer
{
public:
  Json_writer() { out_.precision(17); }

  Json_writer& begin_object() { open('{'); return *this; }
  Json_writer& end_object() { close('}'); return *this; }
  Json_writer& begin_array() { open('['); return *this; }
  Json_writer& end_array() { close(']'); return *this; }

  Json_writer& key(const std::string& name)
  {
    separate();
    write_string(name);
    out_ << ": ";
    after_key_ = true;
    return *this;
  }

  // Non-finite numbers have no JSON spelling: they are written as null.
  Json_writer& value(double x)
  {
    separate();
    if(std::isfinite(x))
      out_ << x;
    else
      out_ << "null";
    return *this;
  }
  Json_writer& value(std::size_t x) { separate(); out_ << x; return *this; }
  Json_writer& value(long x) { separate(); out_ << x; return *this; }
  Json_writer& value(int x) { separate(); out_ << x; return *this; }
  Json_writer& value(bool x) { separate(); out_ << (x ? "true" : "false"); return *this; }
  Json_writer& value(const std::string& s) { separate(); write_string(s); return *this; }
  Json_writer& value(const char* s) { return value(std::string(s)); }

  template <typename T>
  Json_writer& field(const std::string& name, const T& x) { return key(name).value(x); }

  template <typename Range>
  Json_writer& array(const std::string& name, const Range& values)
  {
    key(name).begin_array();
    for(const auto& x : values)
      value(x);
    return end_array();
  }

  std::string str() const { return out_.str() + "\n"; }

private:
  void open(char c)
  {
    separate();
    out_ << c;
    first_.push_back(true);
  }

  void close(char c)
  {
    first_.pop_back();
    out_ << c;
  }

  // Writes the comma before every element of an object or array but the first.
  void separate()
  {
    if(after_key_)
    {
      after_key_ = false;
      return;
    }
    if(!first_.empty())
    {
      if(!first_.back())
        out_ << ", ";
      first_.back() = false;
    }
  }

  void write_string(const std::string& s)
  {
    out_ << '"';
    for(unsigned char c : s)
    {
      if(c == '"' || c == '\\')
        out_ << '\\' << c;
      else if(c < 0x20)
      {
        char buffer[8];
        std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
        out_ << buffer;
      }
      else
        out_ << c;
    }
    out_ << '"';
  }

  std::ostringstream out_;
  std::vector<bool> first_;
  bool after_key_ = false;
};

} // namespace Conformal_remeshing_tools

#endif // CGAL_CONFORMAL_REMESHING_TOOLS_JSON_WRITER_H
