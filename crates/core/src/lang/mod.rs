//! The algorithm language: lexer, parser, checker, compiler and VM.
