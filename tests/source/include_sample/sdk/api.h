/* The ABI: reaches nothing. */
