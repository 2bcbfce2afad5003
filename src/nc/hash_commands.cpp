#include "nck/nc/hash_commands.hpp"
namespace nck::nc {
std::string hash_command_name(const HashCommand&) { return "#"; }
}
