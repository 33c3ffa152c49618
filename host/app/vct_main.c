int vct_placeholder_vct_main;
int main(void){return 0;}
