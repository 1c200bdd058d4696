// A page some pixel asked for (virtual_reduce.vert).
layout(location = 0) out uint flag;

void main()
{
    flag = 1u;
}
