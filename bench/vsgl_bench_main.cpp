// Placeholder entry replaced below.
int main() { return 0; }
