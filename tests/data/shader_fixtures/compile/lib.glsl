float helper() { return 0.5; }
