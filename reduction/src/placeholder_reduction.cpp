// Placeholder so the reduction library has a translation unit until its first real source lands.
namespace seflex::reduction { int placeholder_reduction() { return 0; } }
