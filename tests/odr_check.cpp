// The one-definition-rule check's program (BOXLOD_ODR_CHECK): it links every
// object of every library, used or not, so that GCC's link-time -Wodr compares
// each class against every other definition of its name (CMakeLists.txt).
int main() { return 0; }
