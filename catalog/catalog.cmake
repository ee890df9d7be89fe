# Embeds the catalogue files (catalog/commands/**/*.cata) into stella_catalog: a generated
# CatalogFiles.cpp holds each file's text as a raw string literal. Editing a .cata file reruns
# the generator (DEPENDS); adding one re-globs at the next build (CONFIGURE_DEPENDS).
file(GLOB_RECURSE STELLA_CATALOG_FILES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/commands/*.cata)
set(STELLA_CATALOG_GENERATED ${CMAKE_CURRENT_BINARY_DIR}/CatalogFiles.cpp)
add_custom_command(
  OUTPUT ${STELLA_CATALOG_GENERATED}
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/commands
          -DOUTPUT=${STELLA_CATALOG_GENERATED} -P ${CMAKE_CURRENT_SOURCE_DIR}/EmbedCatalog.cmake
  DEPENDS ${STELLA_CATALOG_FILES} ${CMAKE_CURRENT_SOURCE_DIR}/EmbedCatalog.cmake
  COMMENT "Embedding the keyword catalogue"
  VERBATIM)
target_sources(stella_catalog PRIVATE ${STELLA_CATALOG_GENERATED})

# Developer tool: load checks, describe, JSON, doc generation, coverage (tools/catalog-coverage).
add_executable(stella-catalog ${CMAKE_CURRENT_SOURCE_DIR}/tool/main.cpp)
target_link_libraries(stella-catalog PRIVATE stella_catalog stella_options)
