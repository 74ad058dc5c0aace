#./:12
#include "c.gls: FragColo'l"
s2