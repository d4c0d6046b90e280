#[==[
Debian 13 installs VTK's and ParaView's Python modules under their tagged names
(`vtkCommonCore.cpython-313-x86_64-linux-gnu.so`: dh_python3 renames them since paraview
5.13.2+dfsg-2), while the exported target files still name `vtkCommonCore.so`. CMake's generated
target file then stops `find_package` with "The imported target VTK::vtkCommonCorePython
references the file ... but this file does not exist" — for every user of the package, whatever
components are asked for, since the package config always includes those files.

A generated target file returns early, without any check, when every target it would create
already exists. So, for each such file whose modules are missing under the exported name and
present under a tagged one, this defines its targets beforehand: it includes a copy of the file
that names the real modules. Nothing is done where the files are right (Debian 12, a fixed
package, VTK's wheels and source builds).

  phongvtk_package_config_directories(<package> <out-var>)
  phongvtk_import_renamed_python_modules(<package config directory>...)

Call it before the `find_package` of that package, in the directory that calls `find_package`.
#]==]
# The folder find_package(<package>) will take: <package>_DIR, or Debian's one folder when nothing
# points elsewhere (no <package>_ROOT, no CMAKE_PREFIX_PATH); empty otherwise, and then nothing is
# patched.
function (phongvtk_package_config_directories package out)
  set(directories)
  if (${package}_DIR)
    set(directories "${${package}_DIR}")
  elseif (NOT ${package}_ROOT AND NOT DEFINED ENV{${package}_ROOT} AND NOT CMAKE_PREFIX_PATH
      AND NOT DEFINED ENV{CMAKE_PREFIX_PATH})
    string(TOLOWER "${package}" lower)
    file(GLOB directories LIST_DIRECTORIES true
      "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/${lower}-*")
    list(LENGTH directories count)
    if (NOT count EQUAL 1)
      set(directories)
    endif ()
  endif ()
  set(${out} "${directories}" PARENT_SCOPE)
endfunction ()

function (phongvtk_import_renamed_python_modules)
  set(work "${CMAKE_BINARY_DIR}/CMakeFiles/PhongVTKDebianPythonTargets")
  foreach (directory IN LISTS ARGN)
    file(GLOB targets_files "${directory}/*Python*-targets.cmake")
    foreach (targets_file IN LISTS targets_files)
      _phongvtk_import_renamed("${targets_file}" "${work}")
    endforeach ()
  endforeach ()
endfunction ()

function (_phongvtk_import_renamed targets_file work)
  get_filename_component(name "${targets_file}" NAME_WE)
  get_filename_component(directory "${targets_file}" DIRECTORY)
  file(READ "${targets_file}" main)
  # The prefix as the file computes it: its directory, then one level up per further step.
  set(prefix "${directory}")
  string(REGEX MATCHALL "get_filename_component\\(_IMPORT_PREFIX \"\\\${_IMPORT_PREFIX}\" PATH\\)"
    steps "${main}")
  foreach (step IN LISTS steps)
    get_filename_component(prefix "${prefix}" DIRECTORY)
  endforeach ()

  file(GLOB config_files "${directory}/${name}-*.cmake")
  # The copies of an earlier configuration (the package may have changed since) go first.
  file(REMOVE_RECURSE "${work}/${name}")
  set(renamed 0)
  set(patched_configs)
  foreach (config_file IN LISTS config_files)
    file(READ "${config_file}" config)
    string(REGEX MATCHALL "\\\${_IMPORT_PREFIX}/[^\"]+\\.so" modules "${config}")
    list(REMOVE_DUPLICATES modules)
    foreach (module IN LISTS modules)
      string(REPLACE "\${_IMPORT_PREFIX}" "${prefix}" path "${module}")
      if (EXISTS "${path}")
        continue ()
      endif ()
      get_filename_component(module_directory "${path}" DIRECTORY)
      get_filename_component(stem "${path}" NAME_WE)
      file(GLOB tagged "${module_directory}/${stem}.cpython-*.so")
      list(LENGTH tagged count)
      if (NOT count EQUAL 1)
        # Missing under every name: leave the file to report it as it would.
        return ()
      endif ()
      get_filename_component(tagged_name "${tagged}" NAME)
      get_filename_component(module_parent "${module}" DIRECTORY)
      string(REPLACE "${module}\"" "${module_parent}/${tagged_name}\"" config "${config}")
      math(EXPR renamed "${renamed} + 1")
    endforeach ()
    get_filename_component(config_name "${config_file}" NAME)
    file(WRITE "${work}/${name}/${config_name}" "${config}")
    list(APPEND patched_configs "${config_name}")
  endforeach ()
  if (renamed EQUAL 0)
    return ()
  endif ()

  # The copy computes the prefix from the original file and includes the copied configurations.
  string(REPLACE "\"\${CMAKE_CURRENT_LIST_FILE}\"" "\"${targets_file}\"" main "${main}")
  string(REPLACE "\${CMAKE_CURRENT_LIST_DIR}/${name}-*.cmake" "${work}/${name}/${name}-*.cmake"
    main "${main}")
  file(WRITE "${work}/${name}/${name}.cmake" "${main}")
  # Targets of other export sets (VTK::CommonCore ...) do not exist yet, and need not before the
  # targets are linked: under a package name of its own the copy records that instead of stopping.
  set(CMAKE_FIND_PACKAGE_NAME PhongVTKRenamedPythonModules)
  include("${work}/${name}/${name}.cmake")
  message(STATUS "PhongVTK: ${renamed} Python module(s) of ${targets_file} found under "
    "their tagged names (Debian's renaming; the exported names do not exist)")
endfunction ()
