#include "py_common.hpp"

#include "nck/core/utf8.hpp"
#include "nck/output/diagnostic_json.hpp"

namespace nck::py {
namespace {

template <class Json>
pyb::object convert(const Json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      pyb::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[pyb::str(it.key())] = convert(it.value());
      return d;
    }
    case nlohmann::json::value_t::array: {
      pyb::list l(j.size());
      std::size_t i = 0;
      for (const auto& v : j) l[i++] = convert(v);
      return l;
    }
    // Every string nck puts in its outputs is UTF-8 (to_utf8); a bad byte is replaced, not raised.
    case nlohmann::json::value_t::string: {
      const std::string& s = j.template get_ref<const std::string&>();
      return pyb::reinterpret_steal<pyb::object>(PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace"));
    }
    case nlohmann::json::value_t::boolean: return pyb::bool_(j.template get<bool>());
    case nlohmann::json::value_t::number_integer: return pyb::int_(j.template get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return pyb::int_(j.template get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return pyb::float_(j.template get<double>());
    default: return pyb::none();
  }
}

}  // namespace

pyb::object to_python(const nlohmann::ordered_json& j) { return convert(j); }
pyb::object to_python(const nlohmann::json& j) { return convert(j); }

void raise(const char* kind, ErrorId id, std::string message, SourceLoc loc) {
  throw NckError{kind, {make_diagnostic(id, std::move(loc), std::move(message))}};
}

pyb::object diagnostic_dict(const Diagnostic& d) {
  nlohmann::ordered_json j = app::diagnostic_json(d);
  j["msg"] = j["message"];  // the name Error.diagnostics had before the one shape
  return to_python(j);
}

pyb::object error_dict(const app::FinalError& e, Severity severity) {
  return to_python(app::final_error_json(e, severity));
}

void register_errors() {
  pyb::register_exception_translator([](std::exception_ptr p) {
    if (!p) return;
    try {
      std::rethrow_exception(p);
    } catch (const NckError& e) {
      pyb::gil_scoped_acquire gil;
      const pyb::object cls = pyb::module_::import("nck._errors").attr(e.kind.c_str());
      pyb::list diags;
      for (const Diagnostic& d : e.diagnostics) diags.append(diagnostic_dict(d));
      const pyb::object err = cls.attr("from_diagnostics")(diags);
      PyErr_SetObject(cls.ptr(), err.ptr());
    }
  });
}

}  // namespace nck::py
