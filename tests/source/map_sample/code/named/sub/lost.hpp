// a file of the map test's sample
