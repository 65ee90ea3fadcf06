/* A shared library that is no fdhcert plug-in: it exports no fdh_plugin_v1. */
int fdh_not_a_plugin(void) {
  return 0;
}
