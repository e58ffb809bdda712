#pragma once
// The sandbox's own readings of what a user types, shared by its commands: every value is checked
// before any work starts and refused with one line naming the option (InputError), and every
// option's help text that lists values comes from the same declarations as the settings.
//
// Does not: parse the command line (CLI11 does, main.cpp turns its errors into one line).
#include <string>

#include <CLI/CLI.hpp>

namespace nimbus::sandbox {

// --time: a finite number of seconds >= 0 whose simulation takes at most
// scene::kMaxSimulationSteps steps at the App's default step.
double parseTime(const std::string& text, const std::string& option = "--time");
// "simulation time in seconds (0 .. 1666667: at most 10^8 steps of 1/60 s)"
std::string timeHelp(const std::string& what = "simulation time in seconds");

// A finite number in (0, max], e.g. --exposure, --budget-ms, --tolerance.
double parsePositive(const std::string& text, const std::string& option, double max, const std::string& unit = "");
// A whole number in [min, max], e.g. --frames.
int parseCount(const std::string& text, const std::string& option, long long min, long long max);

// The help of an option that sets the declared key `key` (--mode, --quality): what it accepts,
// from the key's declaration, and `defaultText`.
std::string settingOptionHelp(const std::string& key, const std::string& lead, const std::string& defaultText);

// The --time option on `cmd`, read as text (parseTime reads it when the command runs).
CLI::Option* addTimeOption(CLI::App* cmd, std::string& text, const std::string& what = "simulation time in seconds");

}  // namespace nimbus::sandbox
