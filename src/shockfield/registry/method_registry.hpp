#pragma once
// The explicit registry of the simulation methods, by the case file's `method` value: each entry
// is the method's plug-in factory (core/method.hpp). The one layer above every method besides
// app/: `shockfield run` (app/run_command.cpp) and the Python module's in-process Simulation
// (python/src) build their methods here, so both run the same code.
#include <map>
#include <string>

#include "shockfield/core/config.hpp"
#include "shockfield/core/method.hpp"

namespace shockfield {

const std::map<std::string, MethodFactory>& method_registry();

/// The factory of the case's `method` (InputError naming the file, the key and the choices).
const MethodFactory& method_factory(const Config& root);

}  // namespace shockfield
