# cmake -DIN=<file> -DOUT=<header> -DNAME=<identifier> -P embed.cmake
# Writes a header that holds the bytes of IN as `inline constexpr unsigned char NAME[]` (and
# NAME_size), so that a text file of the repository (the player of `t2 animate`) is compiled
# into the tool without being pasted into C++ as a string.
file(READ "${IN}" hex HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "(0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,)" "\\1\n" bytes "${bytes}")
string(LENGTH "${hex}" n)
math(EXPR n "${n} / 2")
file(WRITE "${OUT}.tmp" "// Generated from ${IN} by embed.cmake: do not edit.\n#pragma once\n#include <cstddef>\n"
     "inline constexpr unsigned char ${NAME}[] = {\n${bytes}0x00};\n"
     "inline constexpr std::size_t ${NAME}_size = ${n};\n")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.tmp")
