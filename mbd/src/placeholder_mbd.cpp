// Placeholder so the mbd library has a translation unit until its first real source lands.
namespace seflex::mbd { int placeholder_mbd() { return 0; } }
