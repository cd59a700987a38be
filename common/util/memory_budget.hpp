// The memory one command may plan to use. Every count read from a file and every
// parameter combination that sizes a buffer is checked against it before anything is
// allocated, so that a hostile file or setting is refused with what it would need
// instead of exhausting the machine (docs/bad-input.md, "Memory budget").
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace plumbago {

struct Scene;

// The default suits a 24 GB machine: the largest scene the bounds admit leaves room for
// the desktop, the compiler and a second run.
constexpr double kDefaultMemoryBudgetGb = 8;
constexpr double kMaxMemoryBudgetGb = 1 << 20;  // 1 PB: more is a typing error

// Set by `plumbago --memory-budget-gb GB`; throws std::invalid_argument outside
// (0, kMaxMemoryBudgetGb].
void set_memory_budget_gb(double gb);
double memory_budget_gb();

// Bytes of a mesh with these counts through every stage that holds it (the loaders'
// arrays, the curvature, either backend's G-buffer geometry): 1 KiB per triangle and
// 512 B per vertex, measured at about 600 B per triangle on the GPU backend.
double mesh_bytes(double vertices, double triangles);

// Empty when `bytes` fit the budget, else "WHAT would need N GB, over the memory budget
// of B GB (plumbago --memory-budget-gb)".
std::string over_memory_budget(const std::string& what, double bytes);

// Throws std::length_error with over_memory_budget's message when it is not empty.
void check_memory_budget(const std::string& what, double bytes);

// Bytes per pixel of every frame stage's outputs as the reference keeps them (floats): an
// upper bound for one frame of any effects, since a frame holds at most all of them.
double frame_bytes_per_pixel();

// The scene's meshes, its frame's buffers at its size (every frame stage's outputs as
// floats: an upper bound for any effects) and the textures its parameters size (the
// pencil stack, layers x size^2; the paper; the 2D and 3D noise) and the GPU's projection of
// its largest stroke file (a G-buffer at the file's resolution), against the budget;
// the message names the scene and its two largest parts (common/scene/scene_memory.cpp).
void check_scene_memory(const Scene& scene);

}  // namespace plumbago
