// Tables that patch models and meshed models read alike ([material], [visual], [damping]).
#pragma once
#include "model/model_file.hpp"
#include "isosid/common/toml_fields.hpp"

namespace isosid::prep {

using common::TomlView;

format::Material read_material(const TomlView& mat);
void read_visual(const TomlView& top, ModelSpec& m);
void read_damping(const TomlView& top, ModelSpec& m);

}  // namespace isosid::prep
