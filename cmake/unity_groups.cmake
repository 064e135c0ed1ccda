# Unity groups (issue 34, docs/development.md "Build time"): several .cpp files of one folder
# compiled as one translation unit parse the shared headers (Eigen, nlohmann-json, gtest, the
# library's own) and instantiate and optimise Eigen's templates once per group instead of once
# per file.
#
#   geardyn_unity_groups(TARGET <target> SIZE <n> [PREFIX <name>] [ACROSS_FOLDERS]
#                        [EXCLUDE <files>...])
#
# Deals the target's sources that have no UNITY_GROUP yet into groups of at most SIZE files, folder
# by folder in the order they are listed (ACROSS_FOLDERS: all folders together, for a test binary
# whose folders hold a few files each), and turns UNITY_BUILD on (GROUP mode: a source without a
# group is compiled alone). A file that defines a file-local constant at the start of a line in
# an unnamed namespace (`constexpr double kTwoPi = ...`, as many files do) goes to the first
# group of its folder that does not define that name yet: a second definition in one translation
# unit would be a compile error (never a silent change). Other file-local names (helper
# functions, fixtures) must be unique per folder; scripts/unity_clashes.py lists them and the
# test `build.unity_clashes` fails on an overload that two files of one group would create (a
# call could then pick the other file's function silently).
# Files listed in EXCLUDE (a #define before an include, per-file definitions) stay apart.
function(geardyn_unity_groups)
  cmake_parse_arguments(arg "ACROSS_FOLDERS" "TARGET;SIZE;PREFIX" "EXCLUDE" ${ARGN})
  if(NOT arg_PREFIX)
    set(arg_PREFIX ${arg_TARGET})
  endif()
  get_target_property(sources ${arg_TARGET} SOURCES)
  get_target_property(source_dir ${arg_TARGET} SOURCE_DIR)
  set(folders)
  foreach(source ${sources})
    get_source_file_property(group ${source} UNITY_GROUP)
    if(group OR NOT source MATCHES "\\.cpp$" OR source IN_LIST arg_EXCLUDE)
      continue()
    endif()
    get_filename_component(folder ${source} DIRECTORY)
    if(arg_ACROSS_FOLDERS)
      set(folder "")
    endif()
    string(MAKE_C_IDENTIFIER "${arg_PREFIX}_${folder}" key)
    if(NOT key IN_LIST folders)
      list(APPEND folders ${key})
      set(files_${key})
    endif()
    list(APPEND files_${key} ${source})
  endforeach()
  foreach(key ${folders})
    set(group_count 0)
    foreach(source ${files_${key}})
      if(IS_ABSOLUTE ${source})
        file(STRINGS ${source} lines REGEX "^(inline |static )?constexpr [^=(]* k[A-Za-z0-9_]+ =")
      else()
        file(STRINGS ${source_dir}/${source} lines
             REGEX "^(inline |static )?constexpr [^=(]* k[A-Za-z0-9_]+ =")
      endif()
      set(names)
      foreach(line ${lines})
        string(REGEX REPLACE "^.* (k[A-Za-z0-9_]+) =.*$" "\\1" name "${line}")
        list(APPEND names ${name})
      endforeach()
      set(chosen -1)
      if(group_count GREATER 0)
        math(EXPR last "${group_count} - 1")
        foreach(g RANGE ${last})
          list(LENGTH members_${g} size)
          if(size LESS arg_SIZE)
            set(free TRUE)
            foreach(name ${names})
              if(name IN_LIST names_${g})
                set(free FALSE)
              endif()
            endforeach()
            if(free)
              set(chosen ${g})
              break()
            endif()
          endif()
        endforeach()
      endif()
      if(chosen EQUAL -1)
        set(chosen ${group_count})
        set(members_${chosen})
        set(names_${chosen})
        math(EXPR group_count "${group_count} + 1")
      endif()
      list(APPEND members_${chosen} ${source})
      list(APPEND names_${chosen} ${names})
    endforeach()
    math(EXPR last "${group_count} - 1")
    foreach(g RANGE ${last})
      list(LENGTH members_${g} size)
      if(size GREATER 1)
        set_source_files_properties(${members_${g}} TARGET_DIRECTORY ${arg_TARGET}
                                    PROPERTIES UNITY_GROUP ${key}_${g})
      endif()
    endforeach()
  endforeach()
  set_target_properties(${arg_TARGET} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
endfunction()
