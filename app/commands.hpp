#pragma once
/// @file Subcommands of the feticon executable; each file app/<name>_command.cpp adds one.

#include <CLI/CLI.hpp>

namespace feticon::app
{
/// `feticon run [PROBLEM.yaml] [--output DIR] [--set KEY=VALUE ...]`
void register_run_command(CLI::App& app);
/// `feticon export [PROBLEM.yaml] [--set KEY=VALUE ...] --format calculix --output DIR`
void register_export_command(CLI::App& app);
/// `feticon qp --A A.mtx --b b.mtx [--lower l.mtx] [--rtol 1e-5] [--out x.mtx]`
void register_qp_command(CLI::App& app);
/// `feticon bench [PROBLEM.yaml] [--set KEY=VALUE ...] | --mprgp-obstacle N`: one benchmark
/// measurement as a JSON line (bench/run.sh)
void register_bench_command(CLI::App& app);
} // namespace feticon::app
