# SPDX-License-Identifier: GPL-3.0-or-later
# tolturn_target_options(target [RELAXED_QT]): the project's warnings (errors when
# TOLTURN_WARNINGS_AS_ERRORS is on) and strict Qt defines. RELAXED_QT leaves out the defines
# that third-party Qt headers break (QCustomPlot uses the `signals` and `foreach` keywords):
# only the plot backend, which wraps QCustomPlot, uses it.
function(tolturn_target_options target)
    cmake_parse_arguments(arg "RELAXED_QT" "" "" ${ARGN})
    target_compile_options(${target} PRIVATE
        -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
        -Woverloaded-virtual -Wconversion -Wsign-conversion -Wdouble-promotion
        -Wformat=2 -Wimplicit-fallthrough)
    if(TOLTURN_WARNINGS_AS_ERRORS)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
    target_compile_definitions(${target} PRIVATE
        QT_NO_CAST_FROM_ASCII
        QT_NO_CAST_TO_ASCII
        QT_NO_URL_CAST_FROM_STRING
        QT_NO_CAST_FROM_BYTEARRAY
        QT_USE_QSTRINGBUILDER
        QT_DISABLE_DEPRECATED_BEFORE=0x060400)
    if(NOT arg_RELAXED_QT)
        target_compile_definitions(${target} PRIVATE QT_NO_KEYWORDS QT_NO_FOREACH)
    endif()
endfunction()
