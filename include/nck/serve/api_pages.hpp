#pragma once
// The answers of the API that depend on no run: the page and its files,
// the machine, the list keys, the build's version, and a JSON reply. nck
// serve (serve_api.cpp) and nck-hal --serve (apps/hal/hal_api.cpp) give
// the same ones.
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "nck/config/machine.hpp"
#include "nck/serve/http_server.hpp"

namespace nck::app::serve {

HttpReply ok_json(const nlohmann::ordered_json& j);
// The page and the files it loads (no token needed: nothing but code in them).
std::optional<HttpReply> page_file(std::string_view path);
// GET /api/v1/machine.
nlohmann::ordered_json machine_json(const config::Machine& m);
// GET /api/v1/parameters: every list key nck accepts (as `nck params`).
nlohmann::ordered_json parameters_json();
// The `channel` of a GET's query: 1 without one, 0 when it is no number.
std::size_t channel_of(std::string_view target);
// The GETs every server answers alike: errors, parameters, openapi.json,
// version (nullopt: another path).
std::optional<HttpReply> fixed_answer(std::string_view path);

}  // namespace nck::app::serve
