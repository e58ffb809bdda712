float fromA;
