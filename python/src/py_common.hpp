#pragma once
// What the binding files share: JSON to Python objects, and nck's
// diagnostics raised as the Python exception classes of nck/_errors.py.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "nck/core/diagnostic.hpp"
#include "nck/output/output_writers.hpp"

namespace nck::py {

namespace pyb = pybind11;

// A JSON value as dict / list / str / int / float / bool / None.
pyb::object to_python(const nlohmann::ordered_json& j);
pyb::object to_python(const nlohmann::json& j);

// Thrown by the bindings, turned into nck.<kind> (an nck.Error) by the
// translator register_errors() installs: kind is the class name.
struct NckError {
  std::string kind;  // "ConfigError", "ProgramError", "ActionError", "ArgumentError"
  std::vector<Diagnostic> diagnostics;
};
[[noreturn]] void raise(const char* kind, ErrorId id, std::string message, SourceLoc loc = {});
void register_errors();

// A diagnostic as an exception's diagnostics list it: the one shape
// (output/diagnostic_json.hpp) and `msg`, its first name for the message.
pyb::object diagnostic_dict(const Diagnostic& d);
// A run's error or warning as Run.errors lists it: id, ch, line, file, msg,
// then the one shape (app::final_error_json, as --final's errors).
pyb::object error_dict(const app::FinalError& e, Severity severity = Severity::error);

}  // namespace nck::py
