// Placeholder so the io library has a translation unit until its first real source lands.
namespace seflex::io { int placeholder_io() { return 0; } }
