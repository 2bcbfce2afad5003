// libFuzzer target: any bytes as the body of nck serve's POST /api/v1/command,
// the whole path up to the kernel: the message checked against its schema,
// then (an operator command) its typed action checked and resolved against
// the milling example's machine, as the server does (a typed "action" line:
// read by the scenario parser).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "nck/serve/api_message.hpp"
#include "nck/sim/operator_action.hpp"
#include "mill_machine.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const nck::config::Machine* m = nck::fuzz::mill_machine();
  if (!m) return 0;
  nck::Diagnostics diags;
  const auto c = nck::app::serve::parse_api_command(std::string_view(reinterpret_cast<const char*>(data), size),
                                                    m->channels.size(), diags);
  using Kind = nck::app::serve::ApiCommand::Kind;
  if (c && c->kind == Kind::action) (void)nck::sim::check_operator_action({c->action, {}}, *m, diags, "api");
  if (c && c->kind == Kind::action_line) (void)nck::sim::parse_operator_action(c->line, *m, diags);
  return 0;
}
