#version 330 core
#include "/dev/zero"
void main() {}
