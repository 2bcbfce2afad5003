// load_machine: startup.lis -> every list it names -> typed model -> checks.
#include "nck/config/load.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "build.hpp"

namespace nck::config {
namespace {

struct Folder {
  std::filesystem::path dir;
  KeyPolicy keys = KeyPolicy::lenient;  // how its lists' unknown keys are reported
  const LoadOptions* options = nullptr;  // its read_text, when set, stands for the files
  // A path from a list, relative to the machine folder; '\' from ISG/Windows lists accepted.
  std::filesystem::path resolve(std::string rel) const {
    std::replace(rel.begin(), rel.end(), '\\', '/');
    std::filesystem::path p(rel);
    return (p.is_absolute() ? p : dir / p).lexically_normal();
  }
};

std::optional<ListText> read_list(const Folder& f, const std::filesystem::path& path, Diagnostics& d,
                                  SourceLoc from = {}) {
  if (!f.options || !f.options->read_text) return read_list_file(path, path.string(), d, from);
  auto text = f.options->read_text(path);
  if (!text) {
    if (from.file.empty()) from.file = path.string();
    d.add(ErrorId::ConfigFileUnreadable, from, fmt::format("list file '{}' is not in the machine's pack", path.string()));
    return std::nullopt;
  }
  return read_list_text(*text, path.string(), d);
}

// Reads and checks one list named by `key` in startup.lis; empty list when absent.
std::optional<ParamList> read_named(const Folder& f, const ParamList& startup, const std::string& key,
                                    ListKind kind, Diagnostics& d) {
  const ParamValue* v = startup.find(key);
  if (!v || v->text.empty()) return std::nullopt;
  auto path = f.resolve(v->text);
  auto text = read_list(f, path, d, v->loc);
  if (!text) return std::nullopt;
  return ParamList::parse(*text, kind, d, f.keys);
}

void check_count(const ParamList& startup, std::string_view count_key, std::size_t found,
                 std::string_view what, Diagnostics& d) {
  if (!startup.has(count_key)) return;
  auto n = startup.u32(count_key, 0);
  if (n != found)
    d.add(ErrorId::ConfigCountMismatch, startup.loc(count_key),
          fmt::format("{} is {} but startup.lis lists {} {}", count_key, n, found, what));
}

ParamList with_defaults(std::optional<ParamList> list, const std::optional<ParamList>& defaults,
                        ListKind kind) {
  ParamList l = list ? std::move(*list) : ParamList(kind, "");
  if (defaults) l.take_defaults_from(*defaults);
  return l;
}

void load_axes(const Folder& f, const ParamList& st, Machine& m, std::vector<ParamList>& lists, Diagnostics& d) {
  auto idx = st.indices("achs_mds[");
  check_count(st, "zahl_mds", idx.size(), "achs_mds[i] axis lists", d);
  auto defaults = read_named(f, st, "default_achs_mds", ListKind::axis, d);
  for (auto i : idx) {
    auto list = read_named(f, st, fmt::format("achs_mds[{}]", i), ListKind::axis, d);
    if (!list) continue;  // 910001 already reported
    lists.push_back(with_defaults(std::move(list), defaults, ListKind::axis));
    m.axes.push_back(detail::build_axis(lists.back(), d));
  }
}

void load_channels(const Folder& f, const ParamList& st, Machine& m, std::vector<detail::ChannelLists>& lists,
                   Diagnostics& d) {
  auto idx = st.indices("sda_mds[");
  if (idx.empty())
    d.add(ErrorId::ConfigNoChannel, SourceLoc{st.file(), 0, 0}, "startup.lis has no sda_mds[0] channel list");
  check_count(st, "kanal_anzahl", idx.size(), "sda_mds[i] channel lists", d);
  detail::check_no_gaps(idx, st.loc_prefix("sda_mds["), "sda_mds[i]", d);
  auto defaults = read_named(f, st, "default_sda_mds", ListKind::channel, d);
  for (auto i : idx) {
    auto ch = read_named(f, st, fmt::format("sda_mds[{}]", i), ListKind::channel, d);
    if (!ch) continue;
    detail::ChannelLists cl;
    cl.channel = with_defaults(std::move(ch), defaults, ListKind::channel);
    auto other = [&](std::string_view key, ListKind kind) {
      auto l = read_named(f, st, fmt::format("{}[{}]", key, i), kind, d);
      return l ? std::move(*l) : ParamList(kind, "");
    };
    cl.tool = other("werkz_data", ListKind::tool);
    cl.zero = other("nullp_data", ListKind::zero);
    cl.clamp = other("pzv_data", ListKind::clamp);
    ChannelConfig c = detail::build_channel(cl.channel, i + 1, d);
    c.tool_list = cl.tool.file();
    c.zero_list = cl.zero.file();
    c.clamp_list = cl.clamp.file();
    ChannelData data;
    data.tools = detail::build_tools(cl.tool, d);
    data.zero = detail::build_zero(cl.zero);
    data.clamp = detail::build_clamp(cl.clamp);
    m.channels.push_back(std::move(c));
    m.channel_data.push_back(std::move(data));
    lists.push_back(std::move(cl));
  }
}

LoadResult load_machine_unguarded(const std::filesystem::path& folder, const LoadOptions& options) {
  LoadResult r;
  Folder f{folder, options.keys, &options};
  auto startup_path = (folder / "startup.lis").lexically_normal();
  auto text = read_list(f, startup_path, r.diagnostics);
  if (!text) return r;
  ParamList st = ParamList::parse(*text, ListKind::startup, r.diagnostics, f.keys);

  Machine m;
  m.folder = folder;
  m.cycle_time_us = st.u32("cycle_time_us", 1000);
  m.ads_32_bit_comp_mode = st.u32("ads_32_bit_comp_mode", 1) == 1;
  std::vector<ParamList> axis_lists;
  std::vector<detail::ChannelLists> channel_lists;
  load_axes(f, st, m, axis_lists, r.diagnostics);
  load_channels(f, st, m, channel_lists, r.diagnostics);
  if (auto sim = read_named(f, st, "sim_data", ListKind::sim, r.diagnostics)) m.sim = detail::build_sim(*sim);
  for (auto i : st.indices("cycle_path["))  // cycle search path, in index order
    if (const ParamValue* v = st.find(fmt::format("cycle_path[{}]", i)); v && !v->text.empty())
      m.cycle_paths.push_back(f.resolve(v->text));
  detail::check_machine(m, axis_lists, channel_lists, r.diagnostics);
  if (options.capability_warnings) detail::check_capabilities(m, axis_lists, r.diagnostics);
  detail::add_c_axes(m);
  r.machine = std::move(m);
  return r;
}

}  // namespace

LoadResult load_machine(const std::filesystem::path& folder, const LoadOptions& options) {
  // Bad input never throws; this only guards against resource exhaustion.
  try {
    return load_machine_unguarded(folder, options);
  } catch (const std::exception& e) {
    LoadResult r;
    r.diagnostics.add(ErrorId::ConfigFileUnreadable, SourceLoc{folder.string(), 0, 0},
                      fmt::format("loading stopped: {}", e.what()));
    return r;
  }
}

}  // namespace nck::config
