/* ETC1's bit layout: see tex_etc1_block.h. */
#include "tex_etc1_block.h"

int tex_etc1_in_second_half(int flip, int x, int y)
{
	return flip ? y >= 2 : x >= 2;
}

/* Bit position of pixel (x, y) in each 16-bit index plane: the
 * specification numbers pixels down the columns. */
static int index_bit(int x, int y)
{
	return x * 4 + y;
}

static void unpack_indices(const uint8_t block[TEX_ETC1_BLOCK_BYTES], tex_etc1_fields *f)
{
	unsigned msb = (unsigned)block[4] << 8 | block[5];
	unsigned lsb = (unsigned)block[6] << 8 | block[7];
	for (int y = 0; y < 4; y++)
		for (int x = 0; x < 4; x++) {
			int b = index_bit(x, y);
			f->index[y * 4 + x] = (uint8_t)(((msb >> b) & 1u) << 1 | ((lsb >> b) & 1u));
		}
}

/* A 3-bit two's complement delta: 4..7 stand for -4..-1. */
static int delta_value(unsigned bits)
{
	return bits >= 4 ? (int)bits - 8 : (int)bits;
}

void tex_etc1_unpack(const uint8_t block[TEX_ETC1_BLOCK_BYTES], tex_etc1_fields *f)
{
	f->differential = (uint8_t)(block[3] >> 1 & 1u);
	f->flip = (uint8_t)(block[3] & 1u);
	f->table[0] = (uint8_t)(block[3] >> 5 & 7u);
	f->table[1] = (uint8_t)(block[3] >> 2 & 7u);
	for (int c = 0; c < 3; c++) {
		if (f->differential) {
			int base = block[c] >> 3;
			f->base[0][c] = (uint8_t)base;
			f->base[1][c] = (uint8_t)((base + delta_value(block[c] & 7u)) & 31);
		} else {
			f->base[0][c] = (uint8_t)(block[c] >> 4);
			f->base[1][c] = (uint8_t)(block[c] & 15u);
		}
	}
	unpack_indices(block, f);
}

static int fields_in_range(const tex_etc1_fields *f)
{
	int top = f->differential ? 31 : 15;
	if (f->differential > 1 || f->flip > 1 || f->table[0] > 7 || f->table[1] > 7)
		return 0;
	for (int c = 0; c < 3; c++) {
		if (f->base[0][c] > top || f->base[1][c] > top)
			return 0;
		int delta = f->base[1][c] - f->base[0][c];
		if (f->differential && (delta < -4 || delta > 3))
			return 0;
	}
	for (int i = 0; i < 16; i++)
		if (f->index[i] > 3)
			return 0;
	return 1;
}

int tex_etc1_pack(const tex_etc1_fields *f, uint8_t block[TEX_ETC1_BLOCK_BYTES])
{
	if (!fields_in_range(f))
		return -1;
	for (int c = 0; c < 3; c++) {
		if (f->differential)
			block[c] = (uint8_t)(f->base[0][c] << 3 | ((f->base[1][c] - f->base[0][c]) & 7));
		else
			block[c] = (uint8_t)(f->base[0][c] << 4 | f->base[1][c]);
	}
	block[3] = (uint8_t)(f->table[0] << 5 | f->table[1] << 2 | f->differential << 1 | f->flip);
	unsigned msb = 0, lsb = 0;
	for (int y = 0; y < 4; y++)
		for (int x = 0; x < 4; x++) {
			unsigned v = f->index[y * 4 + x];
			msb |= (v >> 1) << index_bit(x, y);
			lsb |= (v & 1u) << index_bit(x, y);
		}
	block[4] = (uint8_t)(msb >> 8);
	block[5] = (uint8_t)msb;
	block[6] = (uint8_t)(lsb >> 8);
	block[7] = (uint8_t)lsb;
	return 0;
}
