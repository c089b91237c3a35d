; includes itself: the nesting limit
.include "top.s"
add r1, r2, r3
