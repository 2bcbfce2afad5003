#include "nck/cli.hpp"
namespace nck::app {
int main_cli(int, char**) { return 0; }
}  // namespace nck::app
