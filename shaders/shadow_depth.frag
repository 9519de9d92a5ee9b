#version 450 core
// The depth pass of a light's shadow map: depth only (no colour attachment).

void main() {}
