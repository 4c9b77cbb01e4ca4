#pragma once
/// The whole public API of the spt core library in one include: meshes and import,
/// conversion to sampling trees, the .spt file, collision models, queries, response
/// and continuous detection. Link spt::core (find_package(spt)).
#include "spt/ccd.hpp"
#include "spt/collision_model.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include "spt/node_id.hpp"
#include "spt/pose.hpp"
#include "spt/query.hpp"
#include "spt/query_scratch.hpp"
#include "spt/recipe.hpp"
#include "spt/response.hpp"
#include "spt/samples.hpp"
#include "spt/sampling_tree.hpp"
#include "spt/selection.hpp"
#include "spt/split_recipe.hpp"
#include "spt/spt_file.hpp"
#include "spt/tree_builder.hpp"
#include "spt/version.hpp"
