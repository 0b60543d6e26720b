// Shared by the libFuzzer harnesses: what counts as a finding.
//
// A reader's documented outcomes for any bytes are: a result, an InputError (the located message the CLI
// prints with exit 2), or std::bad_alloc (the CLI's "out of memory", exit 3). Anything else is a finding:
// a crash or sanitizer report (libFuzzer stops by itself), or an exception of another type, which would
// reach the user without a file and location; it is printed and turned into an abort here.
#pragma once

#include "rollkin/io/input_error.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <typeinfo>

namespace rollkin::fuzz {

template <class F> void expect_documented_outcome(F&& read) {
  try {
    read();
  } catch (const io::InputError&) {
  } catch (const std::bad_alloc&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: undocumented exception %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "finding: exception not derived from std::exception\n");
    std::abort();
  }
}

inline std::string as_text(const unsigned char* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace rollkin::fuzz
