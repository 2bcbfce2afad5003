#include "cli.hpp"

int main(int argc, char** argv) { return nck::app::main_cli(argc, argv); }
