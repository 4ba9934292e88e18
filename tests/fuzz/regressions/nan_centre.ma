1 0 0
v nan 0 0 1
