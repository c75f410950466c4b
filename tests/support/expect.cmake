# Runs a command and checks both its exit status and its output: the runner
# behind every ctest entry that runs the CLI and matches what it prints.
# (ctest's PASS_REGULAR_EXPRESSION alone ignores the exit status, so a
# command that prints the right text and then fails would pass.)
#
#   cmake -P tests/support/expect.cmake -- EXIT REGEX [--drop DROP] COMMAND [ARG...]
#
# Passes when COMMAND exits with status EXIT and its output, stdout followed
# by stderr, matches REGEX: a CMake regular expression, as in
# PASS_REGULAR_EXPRESSION (`.` matches a newline too; `^` and `$` are the
# start and end of the whole output). With --drop, the lines of stderr that
# match DROP are left out first (progress lines). The output is printed
# either way; on a failure, what was wrong comes after it, and cmake exits 1.
# COMMAND runs in the current directory with stdin inherited, with its
# arguments exactly as given. A command killed by a signal has a status
# such as "Segmentation fault".
cmake_minimum_required(VERSION 3.21)
# The arguments after "--", read by position (a CMake list would split an
# argument at a `;`, and drop an empty one).
set(at -1)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(CMAKE_ARGV${i} STREQUAL "--")
    set(at ${i})
    break()
  endif()
endforeach()
math(EXPR first_command "${at} + 3")
if(at EQUAL -1 OR first_command GREATER last)
  message(FATAL_ERROR "usage: cmake -P expect.cmake -- EXIT REGEX [--drop DROP] COMMAND [ARG...]")
endif()
math(EXPR i "${at} + 1")
set(expect_exit "${CMAKE_ARGV${i}}")
math(EXPR i "${at} + 2")
set(expect_regex "${CMAKE_ARGV${i}}")
set(drop "")
if(CMAKE_ARGV${first_command} STREQUAL "--drop")
  math(EXPR i "${at} + 4")
  set(drop "${CMAKE_ARGV${i}}")
  math(EXPR first_command "${at} + 5")
  if(first_command GREATER last)
    message(FATAL_ERROR "expect.cmake: no command to run")
  endif()
endif()
# Each argument quoted as it came: none split, dropped or changed.
set(call "execute_process(COMMAND")
foreach(i RANGE ${first_command} ${last})
  string(APPEND call " \"\${CMAKE_ARGV${i}}\"")
endforeach()
string(APPEND call " RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)")
cmake_language(EVAL CODE "${call}")

if(NOT drop STREQUAL "")
  # Keep the lines of stderr that DROP does not match.
  set(rest "${err}")
  set(err "")
  while(NOT rest STREQUAL "")
    string(FIND "${rest}" "\n" newline)
    if(newline EQUAL -1)
      set(line "${rest}")
      set(rest "")
    else()
      string(SUBSTRING "${rest}" 0 ${newline} line)
      math(EXPR next "${newline} + 1")
      string(SUBSTRING "${rest}" ${next} -1 rest)
      set(line "${line}\n")
    endif()
    if(NOT line MATCHES "${drop}")
      string(APPEND err "${line}")
    endif()
  endwhile()
endif()
set(output "${out}${err}")
# The output as it was (on stderr), for ctest --output-on-failure and ctest -V.
message("${output}")

set(problems "")
if(NOT status STREQUAL expect_exit)
  string(APPEND problems "\nexpect.cmake: the exit status is ${status}, not ${expect_exit}")
endif()
if(NOT output MATCHES "${expect_regex}")
  string(APPEND problems "\nexpect.cmake: the output does not match the regular expression\n  ${expect_regex}")
endif()
if(NOT problems STREQUAL "")
  message(FATAL_ERROR "${problems}")
endif()
