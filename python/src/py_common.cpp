#include "py_common.hpp"

#include "nck/core/utf8.hpp"

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

pyb::str text(const std::string& s) {
  const std::string u = to_utf8(s);
  return pyb::reinterpret_steal<pyb::str>(PyUnicode_DecodeUTF8(u.data(), static_cast<Py_ssize_t>(u.size()), "replace"));
}

}  // namespace

pyb::object to_python(const nlohmann::ordered_json& j) { return convert(j); }
pyb::object to_python(const nlohmann::json& j) { return convert(j); }

void raise(const char* kind, ErrorId id, std::string message, SourceLoc loc) {
  throw NckError{kind, {make_diagnostic(id, std::move(loc), std::move(message))}};
}

pyb::dict diagnostic_dict(const Diagnostic& d) {
  pyb::dict out;
  out["id"] = number(d.id);
  out["severity"] = d.severity == Severity::error ? "error" : "warning";
  out["file"] = text(d.loc.file);
  out["line"] = d.loc.line;
  out["msg"] = text(d.message);
  return out;
}

pyb::dict error_dict(const app::FinalError& e) {
  pyb::dict out;
  out["id"] = e.id;
  out["ch"] = e.channel;
  out["line"] = e.line;
  out["file"] = text(e.file);
  out["msg"] = text(e.msg);
  return out;
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
