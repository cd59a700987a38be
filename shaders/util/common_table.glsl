// Tables of records kept as images (common/util/image.hpp table_image): record i at
// (i % TABLE_ROW, i / TABLE_ROW); TABLE_ROW comes from the program's prelude.
ivec2 table_texel(uint i) { return ivec2(i % uint(TABLE_ROW), i / uint(TABLE_ROW)); }
