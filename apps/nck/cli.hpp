#pragma once
namespace nck::app {
// The nck command line: check, run, parse, fit-curve, params, errors.
int main_cli(int argc, char** argv);
}  // namespace nck::app
