# The CLI bakes indirect light by default (docs/rendering.md, "Baked indirect light"). Tests
# written against the project's plain ambient keep it: included at the end of a tests folder's
# CMakeLists.txt, this gives every test of that folder that names neither TESSERA_BAKE nor
# XDG_CACHE_HOME in its environment (a test about the bake, or a golden of the CLI's default
# picture, which caches its bake in the build tree) TESSERA_BAKE=off.
include(${CMAKE_SOURCE_DIR}/tests/common/env_default.cmake)
tessera_env_default("TESSERA_BAKE|XDG_CACHE_HOME" "TESSERA_BAKE=off")
