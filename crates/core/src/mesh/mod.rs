//! Winged-edge and half-edge mesh structures.
