#pragma once
// The database schema, as numbered migrations applied in order: the one place it is written.
//
// Why numbered? A server upgraded over an old database applies only the migrations after the
// version it records (the schema_version table), each in its own transaction; a database from a
// newer server is refused rather than written with the wrong idea of its tables.
#include <span>

namespace polar::server {

struct Migration {
    int version;       // 1, 2, … in order
    const char* what;  // one line, for the log
    const char* sql;   // statements separated by ';', in SQL every database here runs
};

// Every migration, oldest first.
std::span<const Migration> migrations();

}  // namespace polar::server
