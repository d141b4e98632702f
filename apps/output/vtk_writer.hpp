#pragma once
// Legacy ASCII VTK of one solved state, for ParaView: an unstructured grid of the deformed
// configuration (reference + displacement). Each element is one cell, in model order: a
// VTK_POLY_LINE through its nodes in element order (first, interior..., last), or a VTK_VERTEX
// for a one-node element (a point mass). Point data: displacement and reaction vectors. Cell
// data: tension, the mean of the element's integration-point tensions (0 for an element that
// reports none).
#include <string>

#include "apps/output/result_frame.hpp"
#include "libstruct/model/model.hpp"

namespace flexmoor::app {

// Writes the file at `path`, atomically (atomic_output.hpp: a symbolic link there is replaced, not
// followed). Throws std::runtime_error, before anything is written, when a value is NaN or
// infinite or the frame does not match the model, and when the file cannot be written.
void writeVtk(const std::string& path, const model::Model& model, const ResultFrame& frame);

}  // namespace flexmoor::app
