# Prints a file (cmake -DFILE=path -P print_file.cmake), for a test that matches its text.
file(READ "${FILE}" text)
message("${text}")
