#pragma once
// The parsers as the fuzzer calls them in-process (in a fork: sandbox.hpp): each reads one file
// the way shockfield's commands do and touches everything it returned. Shared by the full
// fuzzer (targets.cpp) and by the sanitized parser-only driver of CI (parser_targets.cpp), so
// these need only the parser sources (tests/fuzz/CMakeLists.txt, SHOCKFIELD_FUZZ_PARSER_SOURCES).
#include <filesystem>

namespace shockfield::fuzz {

/// A LAMMPS dump: every frame, its ids, types and positions.
void parse_dump(const std::filesystem::path& file);
/// An extended XYZ file: every frame, its ids, types and positions.
void parse_extxyz(const std::filesystem::path& file);
/// A field file (.csv, .vtk, .vti).
void parse_field(const std::filesystem::path& file);
/// An EAM or ADP file by its extension: .eam (funcfl), .eam.alloy (setfl), .eam.fs
/// (Finnis-Sinclair), .adp (setfl with the u and w tables).
void parse_eam(const std::filesystem::path& file);
/// A pair_style table file: its sections M11, M22 and M12 (those of the cross-check's pair.table).
void parse_pair_table(const std::filesystem::path& file);
/// A LAMMPS data file, periodic in x, y and z.
void parse_data(const std::filesystem::path& file);
/// A particle frame (.vtp, .pvtp: `analyze geometry`, `analyze stats --bin-size`) with its point
/// array `radius`, every value touched.
void parse_point_frame(const std::filesystem::path& file);
/// A point set (`analyze geometry`): 2D for a .txt file, else 3D.
void parse_points(const std::filesystem::path& file);
/// A case file: the TOML, then the case reader of its method where it needs no simulation
/// (md, granular, phasefield), then the check for keys nobody read.
void parse_case(const std::filesystem::path& file);
/// A PD point cloud (pd::read_cloud): cloud_<d>d.txt as a d-dimensional body, then its bounds.
void parse_pd_cloud(const std::filesystem::path& file);
/// Formulas of case files (core/expression.hpp), one a line: each compiled, then evaluated at three
/// points (a syntax error becomes the InputError the case reader makes of it).
void parse_formulas(const std::filesystem::path& file);
/// A PD velocity file (pd::read_point_velocities) for the 3 × 2 lattice of 1 mm.
void parse_pd_velocities(const std::filesystem::path& file);
/// A material file (materials::MaterialFile::load) and every value it gives.
void parse_material(const std::filesystem::path& file);
/// A checkpoint: checksum verified (every item read), then its step counter.
void parse_checkpoint(const std::filesystem::path& file);

}  // namespace shockfield::fuzz
