float helper() {
    return 1.0;
}
float broken() { return undefined_thing; }
