// Tables that patch models and meshed models read alike ([material], [quadrature], [visual],
// [damping]) and their names.
#pragma once
#include "model/model_file.hpp"
#include "isosid/common/toml_fields.hpp"

namespace isosid::prep {

using common::TomlView;

format::Material read_material(const TomlView& mat);
/// t's "name": not empty, no '/', not among `seen` (then added to it).
std::string unique_name(const TomlView& t, std::vector<std::string>& seen);
void read_quadrature(const TomlView& top, ModelSpec& m);
void read_visual(const TomlView& top, ModelSpec& m);
void read_damping(const TomlView& top, ModelSpec& m);

}  // namespace isosid::prep
