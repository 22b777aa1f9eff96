#pragma once
// engine/files: reading files the program did not just write itself.
//
// Owns: the one checked reader (CheckedFile: regular files only, opened
// without blocking, a size cap per kind checked before a byte is read),
// streaming by bounded lines (LineReader), the caps of every kind
// (FileKinds.h), and how a file name that is not UTF-8 is shown
// (PrintableName.h).
// Must not know: any format, Lua, threads, devices. Standard library and
// POSIX only; every other library may use it.

#include "engine/files/CheckedFile.h"
#include "engine/files/FileKinds.h"
#include "engine/files/FileReadError.h"
#include "engine/files/LineReader.h"
#include "engine/files/PrintableName.h"
